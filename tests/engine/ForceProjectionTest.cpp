/// @file ForceProjectionTest.cpp
/// The CPU reference of the force field and its projection (engine/reference/ForceField.h,
/// ForceProjection.h): the weights against the cache's Hodge stars, the orthonormality round
/// trip, buoyancy of a uniform temperature (a gradient: no div-free part), splat signs, the
/// dual-cell mean on finer smoke grids, and both across periodic seams.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/reference/ForceField.h"
#include "engine/reference/ForceProjection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellDec.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"
#include "tests/support/SyntheticBases.h"

namespace modeflow {
namespace {

/// One byte per smoke cell, 1 for fluid: `byCentre` where the smoke cell's centre lies inside the
/// unit disk or ball, else where the basis cell holding it has a part inside Ω (cellFraction > 0).
std::vector<std::uint8_t> smokeMask(const BasisCache& cache, int scale, bool byCentre) {
    const MacGrid basis = MacGrid::fromSpec(cache.grid), smoke = basis.refined(scale);
    std::vector<std::uint8_t> mask(std::size_t(smoke.cellCount()));
    for (int z = 0; z < smoke.cells[2]; ++z)
        for (int y = 0; y < smoke.cells[1]; ++y)
            for (int x = 0; x < smoke.cells[0]; ++x) {
                const double cx = smoke.cellCentre(0, x), cy = smoke.cellCentre(1, y);
                const double cz = smoke.dim == 3 ? smoke.cellCentre(2, z) : 0.0;
                const std::int64_t cell =
                    basis.cellIndex(x / scale, y / scale, basis.dim == 3 ? z / scale : 0);
                mask[std::size_t(smoke.cellIndex(x, y, z))] =
                    byCentre ? cx * cx + cy * cy + cz * cz < 1.0
                             : cache.cellFraction[std::size_t(cell)] > 0.0;
            }
    return mask;
}

/// 1 on the fluid smoke cells of `mask`, 0 elsewhere (what the smoke advection leaves outside Ω).
std::vector<double> onesInside(const std::vector<std::uint8_t>& mask) {
    std::vector<double> field(mask.size());
    for (std::size_t c = 0; c < mask.size(); ++c) field[c] = mask[c] ? 1.0 : 0.0;
    return field;
}

TEST(ForceProjection, DensityWeightIsTheDualEdgeLengthThatTheStarsImply) {
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d()}) {
        const int n = cache->grid.dim;
        const CubicalComplex complex(cache->grid);
        const MacGrid grid = MacGrid::fromSpec(cache->grid);
        const Eigen::VectorXd w = projectionWeights(*cache, FaceQuantity::Density);
        // F = g |f ∩ Ω| with |f ∩ Ω| = |dual edge| / ⋆ (what the precompute's stars encode).
        const Eigen::VectorXd g = testing::randomVector(Eigen::Index(cache->faces.size()), 5);
        Eigen::VectorXd starFlux(g.size());
        int whole = 0;
        for (std::size_t d = 0; d < cache->faces.size(); ++d) {
            const Element e = complex.element(n - 1, cache->faces[d]);
            const FaceLocation face = locateFace(grid, cache->faces[d]);
            ASSERT_EQ(e.pos, face.pos);
            ASSERT_EQ(e.axes, ((1u << n) - 1) & ~(1u << face.axis))
                << "the two face numberings differ";
            const auto i = Eigen::Index(d);
            const double dual = dualMeasure(cache->grid, e);
            EXPECT_EQ(dual, w[i]) << "DOF " << d;
            const double cutArea = dual / cache->faceStar[i];
            EXPECT_LE(cutArea, grid.faceArea(face.axis) * (1.0 + 1e-12));
            whole +=
                std::abs(cutArea - grid.faceArea(face.axis)) <= 1e-12 * grid.faceArea(face.axis);
            starFlux[i] = cache->faceStar[i] * g[i] * cutArea;
        }
        EXPECT_GT(whole, 0);
        const Eigen::VectorXd reference = cache->velocity.modes.transpose() * starFlux;
        const Eigen::VectorXd f = reference::projectForce(*cache, g, FaceQuantity::Density);
        EXPECT_LE((f - reference).lpNorm<Eigen::Infinity>(),
                  1e-13 * reference.lpNorm<Eigen::Infinity>());
    }
}

TEST(ForceProjection, ProjectingAReconstructedFieldGivesTheStateBack) {
    const BasisCache synthetic = testing::syntheticBasis(testing::boxGrid(3, 5), 12, 2);
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d(), &synthetic}) {
        const Eigen::VectorXd v = testing::randomVector(cache->velocity.modes.cols(), 9);
        const std::vector<double> field = reference::reconstructFaceField(*cache, v);
        const Eigen::VectorXd back = reference::projectFaceField(*cache, field);
        EXPECT_LE((back - v).lpNorm<Eigen::Infinity>(), 1e-12 * v.lpNorm<Eigen::Infinity>());
        // The same as a density: g = u A ⋆ / h (the flux spread over the cut face).
        const MacGrid grid = MacGrid::fromSpec(cache->grid);
        Eigen::VectorXd g(Eigen::Index(cache->faces.size()));
        for (std::size_t d = 0; d < cache->faces.size(); ++d) {
            const int axis = locateFace(grid, cache->faces[d]).axis;
            g[Eigen::Index(d)] = field[std::size_t(cache->faces[d])] * grid.faceArea(axis) *
                                 cache->faceStar[Eigen::Index(d)] / grid.spacing[axis];
        }
        const Eigen::VectorXd viaDensity =
            reference::projectForce(*cache, g, FaceQuantity::Density);
        EXPECT_LE((viaDensity - v).lpNorm<Eigen::Infinity>(), 1e-12 * v.lpNorm<Eigen::Infinity>());
    }
}

/// |f|∞ over the largest Σ_d |Ψ_k[d] w_d g_d|: how much of the force survives the projection.
double survivingFraction(const BasisCache& cache, const Eigen::VectorXd& g) {
    const Eigen::VectorXd w = projectionWeights(cache, FaceQuantity::Density);
    const Eigen::VectorXd f = reference::projectForce(cache, g, FaceQuantity::Density);
    const Eigen::VectorXd scale =
        cache.velocity.modes.cwiseAbs().transpose() * w.cwiseProduct(g).cwiseAbs();
    return f.lpNorm<Eigen::Infinity>() / scale.maxCoeff();
}

TEST(ForceProjection, UniformBuoyancyIsAGradientAndProjectsToZero) {
    // A uniform vertical force is ∇(b z): the div-free, free-slip modes see none of it. The smoke
    // is 0 outside its fluid mask; with the mask the dual-cell mean ignores those zeros.
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d()}) {
        for (const int scale : {1, 2, 3}) {
            const MacGrid smoke = MacGrid::fromSpec(cache->grid).refined(scale);
            const std::vector<double> everywhere(std::size_t(smoke.cellCount()), 1.0);
            const std::vector<std::uint8_t> cellMask = smokeMask(*cache, scale, false);
            const std::vector<std::uint8_t> centreMask = smokeMask(*cache, scale, true);
            const std::vector<double> inCells = onesInside(cellMask),
                                      inCentres = onesInside(centreMask);
            auto surviving = [&](std::span<const double> t, std::span<const std::uint8_t> mask) {
                return survivingFraction(
                    *cache, reference::forceDensity(*cache, {2.0, scale, t, mask}, {}));
            };
            const double uniform = surviving(everywhere, {});
            const double byCells = surviving(inCells, cellMask);
            const double byCentres = surviving(inCentres, centreMask);
            const double unmasked = surviving(inCentres, {});
            std::cout << cache->grid.dim << "D, smoke scale " << scale
                      << ": projected uniform buoyancy / its largest term: T = 1 everywhere "
                      << uniform << "; T = 0 outside the mask: basis-cell mask " << byCells
                      << ", cell-centre mask " << byCentres << ", no mask " << unmasked << "\n";
            EXPECT_LE(uniform, 1e-12);
            // Every DOF face's dual cell holds fluid smoke cells of a basis-cell mask: still exact.
            EXPECT_LE(byCells, 1e-12);
            // A cell-centre mask can leave a cut face without fluid smoke (then g = 0); counting
            // the zeros outside Ω weakens the force next to every wall, which is worse.
            EXPECT_LE(byCentres, unmasked);
            EXPECT_GT(unmasked, 1e-3);
        }
    }
}

TEST(ForceProjection, DualCellMeanCoversHalfACellEachSideWithHalfEndCellsForOddScales) {
    const MacGrid basis = MacGrid::fromSpec(testing::boxGrid(2, 4));
    const int scale = 3;
    const MacGrid smoke = basis.refined(scale);
    const FaceLocation face{1, {0, 1, 0}};  // up face between basis cells (0, 0) and (0, 1)
    // Dual cell: smoke x 0..2, y from 3 − 1.5 to 3 + 1.5: rows 1 and 4 half, rows 2 and 3 whole.
    for (const auto& [x, y, expected] :
         {std::tuple{0, 1, 0.5 / 9}, std::tuple{2, 2, 1.0 / 9}, std::tuple{1, 3, 1.0 / 9},
          std::tuple{1, 4, 0.5 / 9}, std::tuple{1, 0, 0.0}, std::tuple{1, 5, 0.0},
          std::tuple{3, 2, 0.0}}) {
        std::vector<double> temperature(std::size_t(smoke.cellCount()), 0.0);
        temperature[std::size_t(smoke.cellIndex(x, y, 0))] = 1.0;
        EXPECT_DOUBLE_EQ(reference::dualCellTemperature(basis, scale, face, temperature, {}),
                         expected)
            << x << ", " << y;
    }
    // A linear temperature averages to its value at the face centre, for any scale, 2D and 3D.
    for (const int dim : {2, 3})
        for (const int s : {1, 2, 3, 4}) {
            const MacGrid b = MacGrid::fromSpec(testing::boxGrid(dim, 4)), fine = b.refined(s);
            auto linear = [](const Vec3& p) { return 0.3 + 0.7 * p[0] - 1.1 * p[1] + 0.4 * p[2]; };
            std::vector<double> temperature(std::size_t(fine.cellCount()));
            for (int z = 0; z < fine.cells[2]; ++z)
                for (int y = 0; y < fine.cells[1]; ++y)
                    for (int x = 0; x < fine.cells[0]; ++x)
                        temperature[std::size_t(fine.cellIndex(x, y, z))] =
                            linear({fine.cellCentre(0, x), fine.cellCentre(1, y),
                                    dim == 3 ? fine.cellCentre(2, z) : 0.0});
            const int up = upAxis(b);
            for (std::int64_t f = b.faceOffset(up); f < b.faceOffset(up) + b.faceCount(up); ++f) {
                const FaceLocation location = locateFace(b, f);
                if (location.pos[up] == 0 || location.pos[up] == b.cells[up]) continue;
                EXPECT_NEAR(reference::dualCellTemperature(b, s, location, temperature, {}),
                            linear(faceCentre(b, location)), 1e-13)
                    << dim << "D, scale " << s << ", face " << f;
            }
        }
}

TEST(ForceProjection, OnAPeriodicUpAxisTheSeamFacesDualCellReachesAcrossIt) {
    // Periodic along y (up in 2D), smoke scale 3: the up face on the seam (y = 0) averages the
    // smoke rows −2 … 1, that is the top two rows 10 and 11 and the bottom two 0 and 1, the end
    // rows (10 and 1) at half weight.
    GridSpec spec = testing::boxGrid(2, 4);
    spec.periodic = {false, true, false};
    const MacGrid basis = MacGrid::fromSpec(spec), smoke = basis.refined(3);
    const FaceLocation seam{1, {1, 0, 0}};
    for (const auto& [row, expected] :
         {std::pair{11, 1.0 / 3}, std::pair{10, 1.0 / 6}, std::pair{0, 1.0 / 3},
          std::pair{1, 1.0 / 6}, std::pair{9, 0.0}, std::pair{2, 0.0}}) {
        std::vector<double> temperature(std::size_t(smoke.cellCount()), 0.0);
        for (int x = 3; x < 6; ++x) temperature[std::size_t(smoke.cellIndex(x, row, 0))] = 1.0;
        EXPECT_DOUBLE_EQ(reference::dualCellTemperature(basis, 3, seam, temperature, {}), expected)
            << "row " << row;
    }
}

TEST(ForceProjection, OnAPeriodicAxisASplatPastOneEndPushesAtTheOther) {
    // The channel around a disk, periodic along x over [0, 2]: a splat a box length to the right
    // is the same splat, and one on the seam pushes at both ends.
    const BasisCache& cache = testing::periodicChannel2d();
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const ForceSplat nearStart{{0.05, 0.5, 0.0}, {1.0, 0.5, 0.0}, 0.2};
    ForceSplat pastEnd = nearStart;
    pastEnd.centre[0] += 2.0;
    const Eigen::VectorXd g =
        reference::forceDensity(cache, {}, std::vector<ForceSplat>{nearStart});
    const Eigen::VectorXd same =
        reference::forceDensity(cache, {}, std::vector<ForceSplat>{pastEnd});
    EXPECT_LE((g - same).lpNorm<Eigen::Infinity>(), 1e-14 * g.lpNorm<Eigen::Infinity>());
    double farEnd = 0.0;
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const FaceLocation face = locateFace(grid, cache.faces[d]);
        if (faceCentre(grid, face)[0] > 1.8) farEnd = std::max(farEnd, g[Eigen::Index(d)]);
    }
    std::cout << "splat at x = 0.05 of radius 0.2: largest push at x > 1.8 " << farEnd << " (peak "
              << g.maxCoeff() << ")\n";
    EXPECT_GT(farEnd, 0.3 * g.maxCoeff());
}

TEST(ForceProjection, SplatsPushAlongTheirForce) {
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d()}) {
        const int n = cache->grid.dim;
        const MacGrid grid = MacGrid::fromSpec(cache->grid);
        for (int axis = 0; axis < n; ++axis)
            for (const double sign : {1.0, -1.0}) {
                ForceSplat splat;
                splat.centre = {0.15, -0.2, n == 3 ? 0.1 : 0.0};
                splat.force[axis] = 3.0 * sign;
                splat.radius = 0.35;
                const std::vector<ForceSplat> splats{splat};
                const Eigen::VectorXd g = reference::forceDensity(*cache, {}, splats);
                // The density itself: force · n times the Gaussian at the face centre.
                for (std::size_t d = 0; d < cache->faces.size(); ++d) {
                    const FaceLocation face = locateFace(grid, cache->faces[d]);
                    const Vec3 x = faceCentre(grid, face);
                    double r2 = 0.0;
                    for (int a = 0; a < n; ++a)
                        r2 += (x[a] - splat.centre[a]) * (x[a] - splat.centre[a]);
                    EXPECT_NEAR(
                        g[Eigen::Index(d)],
                        face.axis == axis ? splat.force[axis] * std::exp(-r2 / 0.35 / 0.35) : 0.0,
                        1e-14);
                }
                // The velocity the modal force makes (v = f): net flow along the force near the
                // centre.
                const std::vector<double> u = reference::reconstructFaceField(
                    *cache, reference::projectForce(*cache, g, FaceQuantity::Density));
                double momentum = 0.0;
                for (std::int64_t f = grid.faceOffset(axis);
                     f < grid.faceOffset(axis) + grid.faceCount(axis); ++f) {
                    const Vec3 x = faceCentre(grid, locateFace(grid, f));
                    double r2 = 0.0;
                    for (int a = 0; a < n; ++a)
                        r2 += (x[a] - splat.centre[a]) * (x[a] - splat.centre[a]);
                    if (r2 < 0.35 * 0.35) momentum += u[std::size_t(f)];
                }
                EXPECT_GT(momentum * sign, 0.0) << n << "D, axis " << axis << ", sign " << sign;
            }
    }
}

TEST(ForceProjection, BadInputsAreRefused) {
    const BasisCache& cache = testing::disk2d();
    const std::vector<double> wrong(7, 1.0);
    EXPECT_THROW(reference::forceDensity(cache, {1.0, 1, wrong, {}}, {}), Error);
    const MacGrid smoke = MacGrid::fromSpec(cache.grid).refined(2);
    const std::vector<double> right(std::size_t(smoke.cellCount()), 1.0);
    EXPECT_THROW(
        reference::forceDensity(cache, {1.0, 2, right, std::vector<std::uint8_t>(3, 1)}, {}),
        Error);
    EXPECT_THROW(reference::forceDensity(cache, {1.0, 0, right, {}}, {}), Error);
    const std::vector<ForceSplat> flat{ForceSplat{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0.0}};
    EXPECT_THROW(reference::forceDensity(cache, {}, flat), Error);
    EXPECT_THROW(reference::projectForce(cache, Eigen::VectorXd::Zero(3), FaceQuantity::Density),
                 Error);
    EXPECT_THROW(reference::projectFaceField(cache, wrong), Error);
}

}  // namespace
}  // namespace modeflow
