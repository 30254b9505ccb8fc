/// @file ReconstructionTest.cpp
/// The CPU reference of the velocity reconstruction (engine/reference/VelocityReconstruction.h):
/// face fields of real and synthetic bases, their divergence, cell-centre velocities.

#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/reference/VelocityReconstruction.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"
#include "tests/support/SyntheticBases.h"

namespace modeflow {
namespace {

double maxAbs(const std::vector<double>& values) {
    double m = 0.0;
    for (double x : values) m = std::max(m, std::abs(x));
    return m;
}

/// max |div| over cells relative to the largest face flux of the field.
double relativeDivergence(const BasisCache& cache, const std::vector<double>& field) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    double largestFlux = 0.0;
    for (std::int64_t f = 0; f < grid.faceTotal(); ++f)
        largestFlux = std::max(
            largestFlux, std::abs(field[std::size_t(f)]) * grid.faceArea(locateFace(grid, f).axis));
    return maxAbs(reference::faceFieldDivergence(grid, field)) / largestFlux;
}

TEST(Reconstruction, RealBasesGiveDivergenceFreeFaceFieldsOnTheWholeGrid) {
    // The periodic ones: the precompute's faces are MacGrid's, the seam's included, and the
    // divergence of the last cell along a periodic axis takes its upper face across the seam.
    // The whole 3-torus is a closed-form basis: reconstructed by its transforms, no columns.
    for (const BasisCache* cache :
         {&testing::disk2d(), &testing::ball3d(), &testing::periodicChannel2d(),
          &testing::torusAroundDisk2d(), &testing::torus3d()}) {
        const Eigen::Index modes = cache->velocity.eigenvalues.size();
        const Eigen::VectorXd v = testing::randomVector(modes, 3);
        const std::vector<double> field = reference::reconstructFaceField(*cache, v);
        const double divergence = relativeDivergence(*cache, field);
        std::cout << cache->grid.dim << "D real basis, periodic " << cache->grid.periodic[0]
                  << cache->grid.periodic[1] << cache->grid.periodic[2]
                  << ": max |div| / max |flux| = " << divergence << "\n";
        EXPECT_LE(divergence, 1e-12);
        // Each mode alone, too.
        for (Eigen::Index i = 0; i < modes; ++i)
            EXPECT_LE(relativeDivergence(*cache, reference::reconstructFaceField(
                                                     *cache, Eigen::VectorXd::Unit(v.size(), i))),
                      1e-11)
                << "mode " << i;
    }
}

TEST(Reconstruction, ScattersFluxOverWholeFaceAreaAndLeavesOtherFacesZero) {
    for (const int dim : {2, 3}) {
        const BasisCache cache =
            testing::syntheticBasis(testing::boxGrid(dim, dim == 2 ? 9 : 5), 6, 11);
        const MacGrid grid = MacGrid::fromSpec(cache.grid);
        const Eigen::VectorXd v = testing::randomVector(6, 4);
        const Eigen::VectorXd fluxes = cache.velocity.modes * v;
        const std::vector<double> field = reference::reconstructFaceField(cache, v);
        ASSERT_EQ(field.size(), std::size_t(grid.faceTotal()));
        std::vector<bool> isDof(field.size(), false);
        for (std::size_t d = 0; d < cache.faces.size(); ++d) {
            const std::int64_t f = cache.faces[d];
            isDof[std::size_t(f)] = true;
            const double area = grid.faceArea(locateFace(grid, f).axis);
            EXPECT_NEAR(field[std::size_t(f)] * area, fluxes[Eigen::Index(d)],
                        1e-14 * std::abs(fluxes[Eigen::Index(d)]));
        }
        for (std::size_t f = 0; f < field.size(); ++f)
            if (!isDof[f]) {
                EXPECT_EQ(field[f], 0.0) << "face " << f;
            }
    }
}

TEST(Reconstruction, LocateFaceInvertsFaceIndex) {
    for (const int dim : {2, 3})
        for (const bool periodic : {false, true}) {
            GridSpec spec = testing::boxGrid(dim, 4);
            spec.periodic[dim - 1] = periodic;  // n faces along it, not n + 1
            const MacGrid grid = MacGrid::fromSpec(spec);
            EXPECT_EQ(grid.faceCount(dim - 1),
                      periodic ? 4 * grid.cellCount() / 4 : 5 * grid.cellCount() / 4);
            for (std::int64_t f = 0; f < grid.faceTotal(); ++f) {
                const FaceLocation face = locateFace(grid, f);
                EXPECT_EQ(grid.faceIndex(face.axis, face.pos[0], face.pos[1], face.pos[2]), f);
            }
            EXPECT_THROW(locateFace(grid, grid.faceTotal()), Error);
        }
}

TEST(Reconstruction, CellCentreVelocityAveragesTheTwoFacesPerAxis) {
    const MacGrid grid = MacGrid::fromSpec(testing::boxGrid(3, 4));
    // u_a = a linear function of the face centre: the cell-centre mean is its value at the centre.
    std::vector<double> field(std::size_t(grid.faceTotal()));
    auto linear = [](int axis, const Vec3& x) {
        return 1.0 + axis + 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2] * axis;
    };
    for (std::int64_t f = 0; f < grid.faceTotal(); ++f) {
        const FaceLocation face = locateFace(grid, f);
        field[std::size_t(f)] = linear(face.axis, faceCentre(grid, face));
    }
    const std::vector<Vec3> cells = reference::cellCentreVelocity(grid, field);
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const Vec3 centre{grid.cellCentre(0, x), grid.cellCentre(1, y),
                                  grid.cellCentre(2, z)};
                const Vec3& u = cells[std::size_t(grid.cellIndex(x, y, z))];
                for (int a = 0; a < 3; ++a) EXPECT_NEAR(u[a], linear(a, centre), 1e-13);
            }
    // 2D: the third component is 0.
    const MacGrid flat = MacGrid::fromSpec(testing::boxGrid(2, 5));
    const std::vector<Vec3> flatCells = reference::cellCentreVelocity(
        flat, std::vector<double>(std::size_t(flat.faceTotal()), 2.0));
    for (const Vec3& u : flatCells) EXPECT_EQ(u, (Vec3{2.0, 2.0, 0.0}));
}

TEST(Reconstruction, WrongSizesAreRefused) {
    const BasisCache cache = testing::syntheticBasis(testing::boxGrid(2, 6), 4, 1);
    EXPECT_THROW(reference::reconstructFaceField(cache, Eigen::VectorXd::Zero(5)), Error);
    EXPECT_THROW(reference::fluxesToFaceField(cache, Eigen::VectorXd::Zero(3)), Error);
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    EXPECT_THROW(reference::cellCentreVelocity(grid, std::vector<double>(7)), Error);
    EXPECT_THROW(reference::faceFieldDivergence(grid, std::vector<double>(7)), Error);
}

}  // namespace
}  // namespace modeflow
