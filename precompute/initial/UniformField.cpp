/// @file UniformField.cpp
#include "precompute/initial/UniformField.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/core/Vec3Math.h"
#include "precompute/initial/VortexProjection.h"

namespace modeflow {
namespace {

/// Mesh level sets at half the finest grid spacing, as the precompute builds them.
double levelSetVoxel(const GridSpec& grid) {
    double h = grid.spacing(0);
    for (int a = 1; a < grid.dim; ++a) h = std::min(h, grid.spacing(a));
    return 0.5 * h;
}

/// Ω's centroid from the cut-cell fractions (the grid box's centre when they are missing).
Vec3 centroid(const BasisCache& cache) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    Vec3 sum{0.0, 0.0, 0.0};
    double total = 0.0;
    if (cache.cellFraction.size() == std::size_t(grid.cellCount())) {
        for (int z = 0; z < grid.cells[2]; ++z)
            for (int y = 0; y < grid.cells[1]; ++y)
                for (int x = 0; x < grid.cells[0]; ++x) {
                    const double f = cache.cellFraction[std::size_t(grid.cellIndex(x, y, z))];
                    const int at[3] = {x, y, z};
                    for (int a = 0; a < cache.grid.dim; ++a)
                        sum[a] += f * grid.cellCentre(a, at[a]);
                    total += f;
                }
    }
    if (total > 0.0) return {sum[0] / total, sum[1] / total, sum[2] / total};
    Vec3 centre{0.0, 0.0, 0.0};
    for (int a = 0; a < cache.grid.dim; ++a)
        centre[a] = 0.5 * (cache.grid.boundsMin[a] + cache.grid.boundsMax[a]);
    return centre;
}

}  // namespace

double uniformFieldLayer(const BasisCache& cache) {
    const Eigen::VectorXd& k2 = cache.velocity.eigenvalues;
    if (k2.size() == 0) throw Error("uniform field: the basis has no velocity modes");
    return 2.0 * std::numbers::pi / std::sqrt(k2.maxCoeff());
}

UniformField::UniformField(const BasisCache& cache, const std::vector<ShapeSpec>& shapes,
                           const Vec3& direction, double strength, double layer)
    : mGrid(cache.grid),
      mDomain(shapes, cache.grid.dim, levelSetVoxel(cache.grid)),
      mCentre(centroid(cache)),
      mLayer(layer) {
    const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                    direction[2] * direction[2]);
    if (!(length > 0.0)) throw Error("uniform field: the direction must be a non-zero vector");
    if (!(layer > 0.0)) throw Error("uniform field: the wall layer must be positive");
    for (int a = 0; a < 3; ++a) mField[a] = strength * direction[a] / length;
    choosePotential();
}

void UniformField::choosePotential() {
    const int dim = mGrid.dim;
    const auto periodic = [&](int a) { return a < dim && mGrid.isPeriodic(a); };
    // A_i = Σ_j P_ij r_j. Without a periodic axis, the symmetric gauge A = ½ B0 × r (3D) or
    // A_z = B0x r_y − B0y r_x (2D).
    for (Vec3& row : mPotential) row = {0.0, 0.0, 0.0};
    if (!mGrid.anyPeriodic()) {
        if (dim == 2) {
            mPotential[2] = {-mField[1], mField[0], 0.0};
            return;
        }
        for (int a = 0; a < 3; ++a) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            mPotential[c][b] += 0.5 * mField[a];  // ½ B0_a (ê_a × r) = ½ B0_a (r_b ê_c − r_c ê_b)
            mPotential[b][c] -= 0.5 * mField[a];
        }
        return;
    }
    // Along a periodic axis A must not grow, or B would jump at the seam wherever a wall meets
    // it: each component B0_a ê_a = ∇×(r_b ê_c) = ∇×(−r_c ê_b) ((a, b, c) cyclic; 2D: c = z)
    // takes the form whose coordinate runs along a wall-bounded axis.
    for (int a = 0; a < dim; ++a) {
        if (mField[a] == 0.0) continue;
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        if (b < dim && !periodic(b)) {
            mPotential[c][b] += mField[a];
        } else if (c < dim && !periodic(c)) {
            mPotential[b][c] -= mField[a];
        } else if (!periodic(a)) {
            // The section across axis a closes on itself: the flux through it is the same at
            // every a and zero at a's walls, so no field crosses it on average.
            const char* names[] = {"x", "y", "z"};
            throw Error(std::string("uniform field: a component along ") + names[a] +
                        " crosses the walls at the ends of " + names[a] +
                        ", and every other axis is periodic: no divergence-free field without "
                        "flux through the walls crosses them on average; choose a direction "
                        "along a periodic axis");
        } else {
            // A whole torus: the coordinate is taken at its image nearest Ω's centroid, which
            // is exact wherever walls (obstacles) stay clear of the seam opposite the centroid.
            const int axis = b < dim ? b : c;
            mWrapped[axis] = true;
            if (axis == b)
                mPotential[c][b] += mField[a];
            else
                mPotential[b][c] -= mField[a];
        }
    }
}

double UniformField::wallDistance(const Vec3& x) const {
    // χ never exceeds the distance to Ω's wall (Domain.h); the grid box is a wall too, except
    // at the ends of a periodic axis, which meet.
    double d = mDomain.chi(x);
    for (int a = 0; a < mGrid.dim; ++a)
        if (!mGrid.isPeriodic(a))
            d = std::min({d, x[a] - mGrid.boundsMin[a], mGrid.boundsMax[a] - x[a]});
    return d;
}

double UniformField::weight(const Vec3& x) const {
    const double t = std::clamp(wallDistance(x) / mLayer, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

Vec3 UniformField::operator()(const Vec3& x) const {
    Vec3 r{x[0] - mCentre[0], x[1] - mCentre[1], x[2] - mCentre[2]};
    for (int a = 0; a < 3; ++a) {
        if (a >= mGrid.dim) r[a] = 0.0;
        if (!mWrapped[a]) continue;
        const double period = mGrid.boundsMax[a] - mGrid.boundsMin[a];
        r[a] -= period * std::round(r[a] / period);
    }
    Vec3 potential;
    for (int i = 0; i < 3; ++i)
        potential[i] = mPotential[i][0] * r[0] + mPotential[i][1] * r[1] + mPotential[i][2] * r[2];
    // ∇w by central differences: χ has no analytic gradient for meshes and CSG combinations.
    const double step = 1e-4 * mLayer;
    Vec3 gradient{0.0, 0.0, 0.0};
    for (int a = 0; a < mGrid.dim; ++a) {
        Vec3 plus = x, minus = x;
        plus[a] += step;
        minus[a] -= step;
        gradient[a] = (weight(plus) - weight(minus)) / (2.0 * step);
    }
    const double w = weight(x);
    const Vec3 turn = cross(gradient, potential);
    return {w * mField[0] + turn[0], w * mField[1] + turn[1],
            mGrid.dim == 2 ? 0.0 : w * mField[2] + turn[2]};
}

Eigen::VectorXd projectUniformField(const BasisCache& cache, const UniformField& field) {
    return projectFluxes(cache, faceFluxes(cache, [&](const Vec3& x) { return field(x); }));
}

}  // namespace modeflow
