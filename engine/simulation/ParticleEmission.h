#pragma once
/// @file ParticleEmission.h
/// When and where the `[[particles]]` sets put their particles, the same on both backends: a set
/// of `count` has them all from `start`; one of `rate` has floor(rate (t − start)) by time t
/// (rounded up within 1e-9 of a particle, so that time summed step by step counts whole ones),
/// until `end` or the shot's end, whichever comes first. A step from t starts by appending what
/// the sets have emitted by t + dt, set by set, so those particles move during it. A particle's
/// seed is drawn from a counter-based hash of the set's seed, its set and its number in the set
/// (no generator state: a resumed run seeds the same points), uniformly in the set's ball or box,
/// drawn again until it falls in a fluid smoke cell. It starts at rest. The particles a set emits
/// in one step get their ids (places) in the order of the smoke cells they start in, so that
/// neighbours in space are neighbours in memory.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"
#include "engine/simulation/Particles.h"

namespace modeflow {

/// The draws a seed may take before its set is refused as holding no fluid.
inline constexpr int kMaxSeedDraws = 1000;

class ParticleEmission {
public:
    /// `shotEnd`: when the shot's last step ends (frames × steps per frame × dt).
    /// @throw modeflow::Error for more than maxParticleSets sets, or sets emitting more than
    ///        maxParticles particles by shotEnd.
    ParticleEmission(std::vector<ParticleSetSpec> sets, double shotEnd);

    const std::vector<ParticleSetSpec>& sets() const { return mSets; }
    /// How many particles set `set` has emitted by time t.
    std::int64_t emittedBy(std::size_t set, double t) const;
    /// How many all the sets emit in the whole shot: the most a run holds.
    std::int64_t capacity() const { return mCapacity; }

    /// Appends to `particles` what the sets have emitted by time t and `particles` lacks (it
    /// holds the sets' earlier particles, as emit() or restore() left them), seeded in the fluid
    /// cells (`fluidMask`, one byte per cell) of `smokeGrid`. Returns how many it appended.
    /// @throw modeflow::Error naming the set when kMaxSeedDraws draws find no fluid cell.
    std::size_t emit(double t, const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                     Particles& particles);
    /// Takes `particles` as what the sets have emitted so far (a resumed run).
    /// @throw modeflow::Error as requireParticleValues, when they name a set that does not exist,
    ///        or when a set holds more than its whole shot's particles.
    void restore(const Particles& particles);

private:
    std::vector<ParticleSetSpec> mSets;
    double mShotEnd;
    std::int64_t mCapacity = 0;
    std::vector<std::int64_t> mEmitted;  ///< per set, what `particles` holds
};

/// Refuses particles of mismatched sizes or with a non-finite position or velocity.
/// @throw modeflow::Error saying which.
void requireParticleValues(const Particles& particles);

/// The smoke cell holding the world point (the box clamped to its cells, periodic axes wrapped);
/// −1 for a non-finite point.
std::int64_t cellOf(const MacGrid& smokeGrid, const Vec3& point);

/// Whether the world point lies in a fluid cell of `smokeGrid` (the box clamped to its cells).
bool inFluidCell(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                 const Vec3& point);

}  // namespace modeflow
