/// @file SeparableTransformTest.cpp
/// The separable transforms of closed-form bases (engine/basis/SeparableTransform.h) equal the
/// dense materialized columns to round-off: Ψ v and Ψᵀ q on wall boxes, tori and mixed axes, 2D
/// and 3D, even and odd resolutions, for the whole div-free space and for a low band of it.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "engine/basis/SeparableTransform.h"
#include "engine/basis/VelocityBasis.h"
#include "engine/core/Error.h"
#include "engine/format/SeparableModes.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/WholeBoxDofs.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

BasisCache closedFormCache(GridSpec grid, int modes) {
    BasisCache cache;
    cache.grid = grid;
    fillWholeBoxDofs(cache);
    const ClosedFormVelocity basis = closedFormVelocityBasis(grid, {{1, modes}});
    cache.velocity.source = BasisSource::ClosedForm;
    cache.velocity.eigenvalues = basis.eigenvalues;
    cache.velocity.separable = basis.modes;
    return cache;
}

/// Ψ v and Ψᵀ q by the transforms against the columns, relative to the largest value.
void expectEqualToColumns(const GridSpec& grid, int modes, const std::string& what) {
    const BasisCache cache = closedFormCache(grid, modes);
    const Eigen::MatrixXd columns = velocityModeFluxes(grid, cache.faces, cache.velocity.separable);
    const SeparableTransform transform(cache);
    for (std::uint64_t seed : {1u, 2u}) {
        const Eigen::VectorXd v = testing::randomVector(modes, seed);
        const Eigen::VectorXd dense = columns * v;
        const double reconstruction =
            (transform.fluxes(v) - dense).cwiseAbs().maxCoeff() / dense.cwiseAbs().maxCoeff();
        const Eigen::VectorXd q =
            testing::randomVector(Eigen::Index(cache.faces.size()), seed + 10);
        const Eigen::VectorXd projected = columns.transpose() * q;
        const double projection = (transform.transposed(q) - projected).cwiseAbs().maxCoeff() /
                                  projected.cwiseAbs().maxCoeff();
        EXPECT_LE(reconstruction, 1e-13) << what;
        EXPECT_LE(projection, 1e-13) << what;
        if (seed == 1)
            std::printf(
                "[ measured ] %s, %d modes: reconstruction %.1e, projection %.1e (relative)\n",
                what.c_str(), modes, reconstruction, projection);
    }
}

GridSpec grid(std::array<int, 3> res, int dim,
              std::array<bool, 3> periodic = {false, false, false}) {
    GridSpec g = testing::gridScene(res, {0.0, -0.5, 0.25}, {1.0, 0.4, 1.0}, dim).grid;
    g.periodic = periodic;
    return g;
}

TEST(SeparableTransform, EqualsTheColumnsOnWallBoxes) {
    const GridSpec square = grid({12, 9, 1}, 2);
    expectEqualToColumns(square, int(closedFormDivergenceFreeDimension(square)),
                         "2D box 12x9, all");
    expectEqualToColumns(square, 20, "2D box 12x9, low band");
    const GridSpec cube = grid({7, 6, 5}, 3);
    expectEqualToColumns(cube, int(closedFormDivergenceFreeDimension(cube)), "3D box 7x6x5, all");
    expectEqualToColumns(cube, 40, "3D box 7x6x5, low band");
}

TEST(SeparableTransform, EqualsTheColumnsOnToriAndMixedAxes) {
    for (const auto& [res, periodic] :
         {std::pair{std::array<int, 3>{8, 6, 1}, std::array<bool, 3>{true, true, false}},
          std::pair{std::array<int, 3>{7, 5, 1}, std::array<bool, 3>{true, false, false}},
          std::pair{std::array<int, 3>{6, 7, 1}, std::array<bool, 3>{false, true, false}}}) {
        const GridSpec g = grid(res, 2, periodic);
        const std::string name = "2D " + std::to_string(res[0]) + "x" + std::to_string(res[1]) +
                                 " periodic " + std::to_string(periodic[0]) +
                                 std::to_string(periodic[1]);
        expectEqualToColumns(g, int(closedFormDivergenceFreeDimension(g)), name + ", all");
        expectEqualToColumns(g, 15, name + ", low band");
    }
    for (const auto& [res, periodic] :
         {std::pair{std::array<int, 3>{6, 4, 5}, std::array<bool, 3>{true, true, true}},
          std::pair{std::array<int, 3>{5, 6, 4}, std::array<bool, 3>{true, false, true}},
          std::pair{std::array<int, 3>{4, 5, 6}, std::array<bool, 3>{false, true, false}}}) {
        const GridSpec g = grid(res, 3, periodic);
        const std::string name = "3D " + std::to_string(res[0]) + "x" + std::to_string(res[1]) +
                                 "x" + std::to_string(res[2]) + " periodic " +
                                 std::to_string(periodic[0]) + std::to_string(periodic[1]) +
                                 std::to_string(periodic[2]);
        expectEqualToColumns(g, int(closedFormDivergenceFreeDimension(g)), name + ", all");
        expectEqualToColumns(g, 30, name + ", low band");
    }
}

TEST(SeparableTransform,
     TheVelocityBasisTakesTheTransformsOfAClosedFormBasisAndTheColumnsOfAnother) {
    BasisCache cache = closedFormCache(grid({6, 5, 4}, 3), 25);
    const VelocityBasis closed(cache);
    ASSERT_NE(closed.separable(), nullptr);
    EXPECT_EQ(closed.modeCount(), 25);
    const Eigen::VectorXd v = testing::randomVector(25, 3);
    const Eigen::VectorXd fluxes = closed.fluxes(v);
    // The same columns stored densely, as an eigensolved basis stores them.
    BasisCache dense = cache;
    dense.velocity.source = BasisSource::Eigensolve;
    dense.velocity.modes = velocityModeFluxes(cache.grid, cache.faces, cache.velocity.separable);
    const VelocityBasis columns(dense);
    EXPECT_EQ(columns.separable(), nullptr);
    EXPECT_LE((columns.fluxes(v) - fluxes).cwiseAbs().maxCoeff(),
              1e-13 * fluxes.cwiseAbs().maxCoeff());
    EXPECT_THROW(closed.fluxes(testing::randomVector(24, 3)), Error);
    EXPECT_THROW(closed.transposed(testing::randomVector(5, 3)), Error);
    // Not the whole box's faces: refused rather than scattered to the wrong places.
    cache.faces.pop_back();
    EXPECT_THROW(SeparableTransform{cache}, Error);
    EXPECT_THROW(SeparableTransform{dense}, Error);
}

}  // namespace
}  // namespace modeflow
