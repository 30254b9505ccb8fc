#include "engine/reference/ParticleAdvection.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacSampling.h"
#include "engine/simulation/SolidExit.h"

namespace modeflow::reference {
namespace {

Vec3 axpy(const Vec3& x, double a, const Vec3& y) {
    return {x[0] + a * y[0], x[1] + a * y[1], x[2] + a * y[2]};
}

/// `to` brought into the box: wrapped along periodic axes, clamped along walled ones.
Vec3 intoBox(const MacGrid& grid, Vec3 to) {
    for (int a = 0; a < grid.dim; ++a) {
        const double lo = grid.origin[a], length = grid.length(a);
        to[a] = grid.periodic[a] ? lo + (to[a] - lo) - length * std::floor((to[a] - lo) / length)
                                 : std::clamp(to[a], lo, lo + length);
    }
    return to;
}

/// Whether `to` lies beyond a side of `air`'s box the air crosses (ParticleMotion.h: it leaves
/// the run).
bool beyondCrossedSide(const MacGrid& air, const Vec3& to) {
    const std::uint32_t sides = air.crossableSideBits();
    for (int a = 0; a < air.dim; ++a) {
        const double lo = air.origin[a], hi = lo + air.length(a);
        if ((to[a] < lo && (sides >> (2 * a)) & 1u) || (to[a] > hi && (sides >> (2 * a + 1)) & 1u))
            return true;
    }
    return false;
}

}  // namespace

ParticleAdvection::ParticleAdvection(const MacGrid& basisGrid, const MacGrid& smokeGrid,
                                     std::span<const std::uint8_t> fluidMask,
                                     std::vector<ParticleSetSpec> sets, double shotEnd)
    : mBasis(basisGrid),
      mSmoke(smokeGrid),
      mMask(fluidMask),
      mAllFluid(std::all_of(fluidMask.begin(), fluidMask.end(), [](auto m) { return m != 0; })),
      mEmission(std::move(sets), shotEnd) {}

void ParticleAdvection::step(std::span<const double> faceVelocity,
                             std::span<const MovingObstacle> solids, double t, double dt) {
    if (empty()) return;
    mEmission.emit(t + dt, mSmoke, mMask, mParticles);
    std::vector<ParticleResponse> responses;
    for (const ParticleSetSpec& set : mEmission.sets())
        responses.push_back(particleResponse(set, dt));
    std::vector<ObstaclePose> poses;
    for (const MovingObstacle& solid : solids) poses.push_back(solid.poseAt(t + dt));
    const double margin = particleExitMargin(mSmoke);
    const int up = upAxis(mBasis);
    const auto u = [&](const Vec3& x) { return sampleVelocity(mBasis, faceVelocity, x); };

    for (std::size_t i = 0; i < mParticles.size(); ++i) {
        const ParticleResponse& r = responses[mParticles.set[i]];
        Vec3 x0, v0;
        std::copy_n(&mParticles.position[3 * i], 3, x0.begin());
        std::copy_n(&mParticles.velocity[3 * i], 3, v0.begin());
        if (std::isnan(x0[0])) continue;  // it has left the box (as on the device)
        Vec3 x1, v1;
        if (!r.inertial) {
            v1 = u(axpy(x0, 0.5 * dt, u(x0)));
            x1 = axpy(x0, dt, v1);
        } else {
            Vec3 terminal = u(axpy(x0, 0.5 * dt, v0));
            terminal[up] -= r.fall;
            for (int a = 0; a < 3; ++a) {
                const double lag = v0[a] - terminal[a];
                x1[a] = x0[a] + dt * terminal[a] + lag * r.reach;
                v1[a] = terminal[a] + lag * r.decay;
            }
        }
        for (std::size_t o = 0; o < solids.size(); ++o) {
            const auto exit = solidExit(solids[o], x1, poses[o], mSmoke, margin);
            if (!exit) continue;
            x1 = exit->point;
            if (!r.inertial) continue;
            const Vec3 solid = solids[o].velocityOf(x1, poses[o], mSmoke);
            double into = 0.0;
            for (int a = 0; a < 3; ++a) into += (v1[a] - solid[a]) * exit->normal[a];
            if (into < 0.0)
                for (int a = 0; a < 3; ++a) v1[a] -= into * exit->normal[a];
        }
        if (beyondCrossedSide(mBasis, x1)) {  // it leaves the run
            x1.fill(kParticleLeft);
            v1.fill(0.0);
        } else {
            x1 = intoBox(mSmoke, x1);
            if (!mAllFluid && !inFluidCell(mSmoke, mMask, x1)) {
                // Slide: keep each axis's move where it stays in the fluid.
                Vec3 slid = x0;
                for (int a = 0; a < mSmoke.dim; ++a) {
                    const double held = slid[a];
                    slid[a] = x1[a];
                    if (!inFluidCell(mSmoke, mMask, slid)) {
                        slid[a] = held;
                        if (r.inertial) v1[a] = 0.0;
                    }
                }
                x1 = slid;
            }
        }
        std::copy_n(x1.begin(), 3, &mParticles.position[3 * i]);
        std::copy_n(v1.begin(), 3, &mParticles.velocity[3 * i]);
    }
}

void ParticleAdvection::restore(Particles particles) {
    mEmission.restore(particles);
    mParticles = std::move(particles);
}

}  // namespace modeflow::reference
