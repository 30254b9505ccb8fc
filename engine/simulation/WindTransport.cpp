#include "engine/simulation/WindTransport.h"

#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacSampling.h"
#include "engine/dynamics/QuadratureSampling.h"

namespace modeflow {
namespace {

/// The axes the wind blows along (non-zero components).
std::vector<int> windAxes(const MacGrid& grid, const Vec3& wind) {
    std::vector<int> axes;
    for (int a = 0; a < grid.dim; ++a)
        if (wind[a] != 0.0) axes.push_back(a);
    return axes;
}

/// The height over the floor of the faces normal to `normal` at lattice position `p`.
double heightOf(const MacGrid& grid, int normal, const std::array<int, 3>& p) {
    const int up = upAxis(grid);
    return (p[up] + (normal == up ? 0.0 : 0.5)) * grid.spacing[up];
}

}  // namespace

WindTransport::WindTransport(const BasisCache& cache, const WindSpec& wind)
    : mCache(cache), mBasis(cache), mGrid(MacGrid::fromSpec(cache.grid)), mWind(wind) {
    if (cache.kind != BasisKind::Grid) throw Error("wind: a surface basis has no wind");
    for (const double u : wind.velocity)
        if (!std::isfinite(u)) throw Error("wind: the velocity is not finite");
    if (wind.profile == WindProfile::BoundaryLayer) {
        const int up = upAxis(mGrid);
        if (mGrid.periodic[up] || wind.velocity[up] != 0.0)
            throw Error("wind: a boundary layer needs a floor and a wind along it");
        if (!(wind.thickness > 0.0) || !(wind.exponent > 0.0 && wind.exponent <= 1.0))
            throw Error(
                "wind: a boundary layer needs a positive thickness and an exponent in (0, 1]");
    }
    mStar.assign(std::size_t(mGrid.faceTotal()), 0.0);
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const std::int64_t face = cache.faces[d];
        if (face < 0 || face >= mGrid.faceTotal())
            throw Error("wind: face DOF " + std::to_string(face) + " is not a face of the grid");
        mStar[std::size_t(face)] = cache.faceStar[Eigen::Index(d)];
    }
    if (!cache.windBase.empty()) samplePotentialPart(windBaseFlow(cache, wind));
    // f and f' at each row height, per face lattice: the evaluations read these, not pow().
    const int up = upAxis(mGrid);
    for (int c = 0; c < mGrid.dim; ++c)
        for (int j = 0; j < mGrid.faceExtent(c)[up]; ++j) {
            std::array<int, 3> p{0, 0, 0};
            p[up] = j;
            mFactor[c].push_back(windFactor(wind, heightOf(mGrid, c, p)));
            mSlope[c].push_back(windSlope(wind, heightOf(mGrid, c, p)));
        }
}

std::vector<double> WindTransport::gridFluxes(const Eigen::VectorXd& v) const {
    const Eigen::VectorXd dofFluxes = mBasis.fluxes(v);
    std::vector<double> fluxes(std::size_t(mGrid.faceTotal()), 0.0);
    for (std::size_t d = 0; d < mCache.faces.size(); ++d)
        fluxes[std::size_t(mCache.faces[d])] = dofFluxes[Eigen::Index(d)];
    return fluxes;
}

double WindTransport::upVelocityBeside(const std::vector<double>& fluxes, int a,
                                       const std::array<int, 3>& p) const {
    const int up = upAxis(mGrid);
    double sum = 0.0;
    for (const int cell : {p[a] - 1, p[a]})
        for (const int level : {p[up], p[up] + 1}) {
            std::array<int, 3> q = p;
            q[a] = mGrid.wrap(a, cell);
            q[up] = level;
            sum += fluxes[std::size_t(mGrid.faceIndex(up, q[0], q[1], q[2]))];
        }
    return 0.25 * sum / mGrid.faceArea(up);
}

void WindTransport::samplePotentialPart(const std::vector<double>& base) {
    // The fluxes of B − U through the face DOFs: |face ∩ Ω| = |dual edge| / ⋆, the dual edge
    // h_c, or half of it on an open side.
    Eigen::VectorXd potential(Eigen::Index(mCache.faces.size()));
    for (std::size_t d = 0; d < mCache.faces.size(); ++d) {
        const std::int64_t face = mCache.faces[d];
        const FaceLocation at = locateFace(mGrid, face);
        const int c = at.axis;
        const bool onSide = !mGrid.periodic[c] && (at.pos[c] == 0 || at.pos[c] == mGrid.cells[c]);
        potential[Eigen::Index(d)] = (base[std::size_t(face)] - mWind.velocity[c]) *
                                     (onSide ? 0.5 : 1.0) * mGrid.spacing[c] /
                                     mCache.faceStar[Eigen::Index(d)];
    }
    mPotentialB = sample(mCache.quadrature.velocityB, potential);
    mPotentialC = sample(mCache.quadrature.velocityC, potential);
}

void WindTransport::apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    const std::vector<double> fluxes = gridFluxes(v);
    std::vector<double> starred(fluxes.size(), 0.0);  // ⋆·(the change), per grid face
    const int up = upAxis(mGrid);
    const bool layer = mWind.profile == WindProfile::BoundaryLayer;
    for (const int a : windAxes(mGrid, mWind.velocity)) {
        const double u = mWind.velocity[a];
        const double scale = -u / (2.0 * mGrid.spacing[a]);
        // The shear: −U_a f' u'_up on the faces normal to a, in flux units.
        if (layer)
            forEachFace(mGrid, a, [&](std::int64_t face, std::array<int, 3> p) {
                if (mGrid.isWallFace(a, p[a])) return;  // no DOF
                starred[std::size_t(face)] -= mStar[std::size_t(face)] * u *
                                              mSlope[a][std::size_t(p[up])] *
                                              upVelocityBeside(fluxes, a, p) * mGrid.faceArea(a);
            });
        for (int c = 0; c < mGrid.dim; ++c) {
            const int last = mGrid.faceExtent(c)[a] - 1;
            forEachFace(mGrid, c, [&](std::int64_t face, std::array<int, 3> p) {
                // The lattice's face at position q along a: wrapped on a periodic axis; beyond
                // the box, none upstream (the undisturbed inflow) and the last downstream.
                const auto at = [&](int q) -> std::int64_t {
                    if (mGrid.periodic[a]) q = (q + last + 1) % (last + 1);
                    if (q < 0 || q > last) {
                        const bool downstream = (q > last) == (u > 0.0);
                        if (!downstream) return -1;
                        q = q < 0 ? 0 : last;
                    }
                    std::array<int, 3> n = p;
                    n[a] = q;
                    return mGrid.faceIndex(c, n[0], n[1], n[2]);
                };
                // ⋆ between two faces is their mean, so the pairs cancel in vᵀDv (cut faces
                // differ in ⋆; along a whole box's rows it is one value).
                const auto term = [&](std::int64_t other) {
                    if (other < 0) return 0.0;
                    return 0.5 * (mStar[std::size_t(face)] + mStar[std::size_t(other)]) *
                           fluxes[std::size_t(other)];
                };
                starred[std::size_t(face)] += scale * mFactor[c][std::size_t(p[up])] *
                                              (term(at(p[a] + 1)) - term(at(p[a] - 1)));
            });
        }
    }
    Eigen::VectorXd dofs(Eigen::Index(mCache.faces.size()));
    for (std::size_t d = 0; d < mCache.faces.size(); ++d)
        dofs[Eigen::Index(d)] = starred[std::size_t(mCache.faces[d])];
    if (mPotentialB.size() > 0) {
        // Around domain walls, the potential part G = B − U in vorticity form (the structural
        // coefficients' quadrature with G in the velocity slot): −⟨Ψ_k, ω' × G⟩.
        const auto& q = mCache.quadrature;
        const Eigen::VectorXd omega = sample(q.curl, mBasis.fluxes(v));
        addTransposed(q.velocityB, omega.cwiseProduct(mPotentialC), dofs);
        addTransposed(q.velocityC, -omega.cwiseProduct(mPotentialB), dofs);
    }
    out = mBasis.transposed(dofs);
}

const Eigen::MatrixXd& WindTransport::matrix() const {
    if (mMatrix.size() == 0) {
        const int n = size();
        Eigen::MatrixXd d(n, n);
        Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column;
        for (int j = 0; j < n; ++j) {
            unit[j] = 1.0;
            apply(unit, column);
            d.col(j) = column;
            unit[j] = 0.0;
        }
        mMatrix = std::move(d);
    }
    return mMatrix;
}

double WindTransport::outflowPower(const Eigen::VectorXd& v) const {
    const std::vector<double> fluxes = gridFluxes(v);
    double power = 0.0;
    const int up = upAxis(mGrid);
    for (const int a : windAxes(mGrid, mWind.velocity)) {
        if (mGrid.periodic[a]) continue;
        for (int c = 0; c < mGrid.dim; ++c) {
            if (c == a) continue;  // the walls along a: no disturbance crosses them
            const int downstream = mWind.velocity[a] > 0.0 ? mGrid.faceExtent(c)[a] - 1 : 0;
            forEachFace(mGrid, c, [&](std::int64_t face, std::array<int, 3> p) {
                if (p[a] != downstream) return;
                // ⋆F²/h_a = u²·|face ∩ Ω|: the face's share of the side.
                const double flux = fluxes[std::size_t(face)];
                power += 0.5 * std::abs(mWind.velocity[a]) * mFactor[c][std::size_t(p[up])] *
                         mStar[std::size_t(face)] * flux * flux / mGrid.spacing[a];
            });
        }
    }
    return power;
}

double WindTransport::shearPower(const Eigen::VectorXd& v) const {
    if (mWind.profile != WindProfile::BoundaryLayer) return 0.0;
    const std::vector<double> fluxes = gridFluxes(v);
    double power = 0.0;
    const int up = upAxis(mGrid);
    for (const int a : windAxes(mGrid, mWind.velocity))
        forEachFace(mGrid, a, [&](std::int64_t face, std::array<int, 3> p) {
            if (mGrid.isWallFace(a, p[a])) return;
            const double along = fluxes[std::size_t(face)] / mGrid.faceArea(a);
            power += mWind.velocity[a] * mSlope[a][std::size_t(p[up])] * along *
                     upVelocityBeside(fluxes, a, p) * mGrid.cellVolume();
        });
    return power;
}

double windFactor(const WindSpec& wind, double height) {
    if (wind.profile == WindProfile::Uniform || height >= wind.thickness) return 1.0;
    return std::pow(std::max(height, 0.0) / wind.thickness, wind.exponent);
}

double windSlope(const WindSpec& wind, double height) {
    if (wind.profile == WindProfile::Uniform || height >= wind.thickness || height <= 0.0)
        return 0.0;
    return wind.exponent / wind.thickness * std::pow(height / wind.thickness, wind.exponent - 1.0);
}

std::vector<double> windBaseFlow(const BasisCache& cache, const WindSpec& wind) {
    for (const double u : wind.velocity)
        if (!std::isfinite(u)) throw Error("wind: the velocity is not finite");
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    std::vector<double> base(std::size_t(grid.faceTotal()), 0.0);
    if (cache.windBase.empty()) {
        addWind(grid, wind, base);
        return base;
    }
    if (wind.profile != WindProfile::Uniform)
        throw Error(
            "wind: a boundary layer over [[domain]] walls is not built (its held flow is not a "
            "potential flow); blow a uniform wind, or stand the solids in it as [[obstacle]]s");
    const char* axisName[] = {"x", "y", "z"};
    for (int a = 0; a < grid.dim; ++a) {
        if (wind.velocity[a] == 0.0) continue;
        const bool reversed = wind.velocity[a] < 0.0;
        const std::string along = std::string(reversed ? "-" : "+") + axisName[a];
        const std::vector<double>& flow = cache.windBase[std::size_t(2 * a + reversed)];
        if (flow.empty())
            throw Error("wind: the [[domain]] walls let no wind blow along " + along +
                        ": air entering its upstream side finds no way to the downstream one");
        if (flow.size() != base.size())
            throw Error("wind: the cache's base flow along " + along +
                        " is not one value per face");
        // Domain walls that seal the box's sides along a leave the wind no way through.
        bool crosses = grid.periodic[a];
        forEachFace(grid, a, [&](std::int64_t face, std::array<int, 3> p) {
            crosses |= (p[a] == 0 || p[a] == grid.cells[a]) && flow[std::size_t(face)] != 0.0;
        });
        if (!crosses)
            throw Error(std::string("wind: its ") + axisName[a] +
                        " component blows at the box's sides along " + axisName[a] +
                        ", and the [[domain]] walls seal them: no air crosses them");
        const double speed = std::abs(wind.velocity[a]);
        for (std::size_t f = 0; f < base.size(); ++f) base[f] += speed * flow[f];
    }
    return base;
}

Eigen::VectorXd windStokesTarget(const BasisCache& cache, const WindSpec& wind) {
    if (cache.windStokes.empty()) return {};
    Eigen::VectorXd target = Eigen::VectorXd::Zero(cache.velocity.eigenvalues.size());
    for (int a = 0; a < cache.grid.dim; ++a) {
        if (wind.velocity[a] == 0.0) continue;
        const std::vector<double>& c =
            cache.windStokes[std::size_t(2 * a + (wind.velocity[a] < 0.0))];
        if (c.size() != std::size_t(target.size()))
            throw Error("wind: the cache's Stokes correction along axis " + std::to_string(a) +
                        " has " + std::to_string(c.size()) + " modes, the basis " +
                        std::to_string(target.size()));
        target +=
            std::abs(wind.velocity[a]) * Eigen::Map<const Eigen::VectorXd>(c.data(), target.size());
    }
    return target;
}

SimulationSettings withWindTransport(SimulationSettings settings, const BasisCache& cache) {
    if (settings.wind) {
        settings.fluid.linear = std::make_shared<WindTransport>(cache, *settings.wind);
        settings.fluid.viscousTarget = windStokesTarget(cache, *settings.wind);
    }
    return settings;
}

MacGrid withWindThrough(MacGrid grid, const Vec3& wind) {
    for (const int a : windAxes(grid, wind)) grid.flowThrough[a] = !grid.periodic[a];
    return grid;
}

std::array<bool, 6> inflowSides(const MacGrid& grid, const Vec3& wind) {
    std::array<bool, 6> sides = grid.open;
    for (int a = 0; a < grid.dim; ++a)
        if (!grid.periodic[a] && wind[a] != 0.0) sides[std::size_t(2 * a + (wind[a] < 0.0))] = true;
    return sides;
}

MacGrid airGridOf(const GridSpec& spec, const std::optional<WindSpec>& wind) {
    const MacGrid grid = MacGrid::fromSpec(spec);
    return wind ? withWindThrough(grid, wind->velocity) : grid;
}

void addWind(const MacGrid& grid, const WindSpec& wind, std::span<double> faceField) {
    requireFaceField(grid, faceField.size(), "wind face field");
    for (const int a : windAxes(grid, wind.velocity))
        forEachFace(grid, a, [&](std::int64_t face, std::array<int, 3> p) {
            faceField[std::size_t(face)] +=
                wind.velocity[a] * windFactor(wind, heightOf(grid, a, p));
        });
}

}  // namespace modeflow
