/// @file TensorFreeCoefficientsTest.cpp
/// The tensor-free structural coefficients (engine/dynamics/TensorFreeCoefficients.h) against the
/// tensor the precompute assembles from the same quadrature, on real cut-cell bases in 2D and 3D:
/// every entry and every contraction agrees to round-off, the energy identity holds exactly, and
/// a quadrature that does not fit the modes is refused.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/dynamics/CachedCoefficients.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/TensorFreeCoefficients.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"

namespace modeflow {
namespace {

using testing::randomVector;

double relative(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
    return (got - want).norm() / want.norm();
}

class TensorFree : public ::testing::TestWithParam<int> {
protected:
    const BasisCache& cache() const {
        return GetParam() == 2 ? testing::disk2d() : testing::ball3d();
    }
};

TEST_P(TensorFree, EveryEntryIsTheAssembledOne) {
    const auto dense = coefficientsFromCache(cache(), CoefficientStorage::Dense);
    const TensorFreeCoefficients free(cache().velocity.modes, cache().quadrature);
    const int n = free.size();
    double largest = 0.0, worst = 0.0;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                largest = std::max(largest, std::abs(dense->entry(k, i, j)));
                worst = std::max(worst, std::abs(free.entry(k, i, j) - dense->entry(k, i, j)));
            }
    ASSERT_GT(largest, 0.0);
    EXPECT_LT(worst / largest, 1e-12) << "largest entry difference " << worst << " of " << largest;
}

TEST_P(TensorFree, ContractionsAreTheAssembledOnes) {
    const auto dense = coefficientsFromCache(cache(), CoefficientStorage::Dense);
    const auto free = coefficientsFromCache(cache(), CoefficientStorage::TensorFree);
    ASSERT_NE(dynamic_cast<const TensorFreeCoefficients*>(free.get()), nullptr);
    const int n = free->size();
    const Eigen::VectorXd a = randomVector(n, 11), b = randomVector(n, 12);
    Eigen::VectorXd got, want;
    for (const auto& [x, y] : {std::pair{a, b}, std::pair{a, a}}) {
        free->apply(x, y, got);
        dense->apply(x, y, want);
        EXPECT_LT(relative(got, want), 1e-12) << "apply";
    }
    free->advect(a, b, got);  // (advect(a, a) = 0)
    dense->advect(a, b, want);
    EXPECT_LT(relative(got, want), 1e-12) << "advect";
    Eigen::MatrixXd byI, byJ, wantI, wantJ;
    free->linearize(a, b, byI, byJ);
    dense->linearize(a, b, wantI, wantJ);
    EXPECT_LT(relative(byI, wantI), 1e-12) << "linearize, by i";
    EXPECT_LT(relative(byJ, wantJ), 1e-12) << "linearize, by j";
}

TEST_P(TensorFree, AdvectionDoesNoWorkOnTheVelocity) {
    // vᵀ C(a, v) = 0 for any a: the identity behind energy conservation, by construction.
    const TensorFreeCoefficients free(cache().velocity.modes, cache().quadrature);
    const Eigen::VectorXd v = randomVector(free.size(), 21), a = randomVector(free.size(), 22);
    Eigen::VectorXd r;
    free.apply(a, v, r);
    EXPECT_LT(std::abs(v.dot(r)) / (v.norm() * r.norm()), 1e-14) << "vᵀC(a, v) = " << v.dot(r);
}

INSTANTIATE_TEST_SUITE_P(RealBases, TensorFree, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

TEST(TensorFreeCoefficients, RefuseAQuadratureThatDoesNotFitTheModes) {
    BasisCache::Quadrature quadrature = testing::disk2d().quadrature;
    quadrature.velocityC.column.back() = std::int32_t(testing::disk2d().velocity.modes.rows());
    try {
        TensorFreeCoefficients(testing::disk2d().velocity.modes, quadrature);
        FAIL() << "a quadrature referencing a face beyond the modes was taken";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("references face"), std::string::npos) << e.what();
    }
}

TEST(CachedCoefficients, ATensorIsRefusedFromACacheWithoutOne) {
    BasisCache cache = testing::disk2d();
    cache.coefficients = BasisCache::Coefficients{};
    cache.coefficients.storage = BasisCache::Coefficients::Storage::None;
    EXPECT_NE(dynamic_cast<const TensorFreeCoefficients*>(coefficientsFromCache(cache).get()),
              nullptr);
    try {
        coefficientsFromCache(cache, CoefficientStorage::Dense);
        FAIL() << "dense coefficients from a cache without a tensor";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("holds no structural coefficients"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace modeflow
