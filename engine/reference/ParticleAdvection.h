#pragma once
/// @file ParticleAdvection.h
/// The `[[particles]]` on the CPU, in double precision: the sets' emission (ParticleEmission.h)
/// and each step's motion (the rule: engine/simulation/ParticleMotion.h). The reference of the
/// device's ParticleAdvection.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/ParticleEmission.h"
#include "engine/simulation/ParticleMotion.h"
#include "engine/simulation/Particles.h"

namespace modeflow::reference {

class ParticleAdvection {
public:
    /// `fluidMask` (one byte per cell of `smokeGrid`, non-zero in the fluid) must outlive it.
    /// @throw modeflow::Error as ParticleEmission does.
    ParticleAdvection(const MacGrid& basisGrid, const MacGrid& smokeGrid,
                      std::span<const std::uint8_t> fluidMask, std::vector<ParticleSetSpec> sets,
                      double shotEnd);

    /// The step from t: what the sets emit by t + dt, then every particle moved in
    /// `faceVelocity` (a face field of the basis grid), pushed out of `solids` where they are at
    /// t + dt and kept in the domain.
    void step(std::span<const double> faceVelocity, std::span<const MovingObstacle> solids,
              double t, double dt);

    const Particles& particles() const { return mParticles; }
    /// @throw modeflow::Error as ParticleEmission::restore.
    void restore(Particles particles);
    bool empty() const { return mEmission.sets().empty(); }

private:
    MacGrid mBasis, mSmoke;
    std::span<const std::uint8_t> mMask;
    bool mAllFluid;
    ParticleEmission mEmission;
    Particles mParticles;
};

}  // namespace modeflow::reference
