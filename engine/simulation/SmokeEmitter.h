#pragma once
/// @file SmokeEmitter.h
/// A smoke and heat source (engine/README.md, a scene's `[[source]]`): a ball or a box (a disk or a
/// rectangle in 2D) or a closed mesh's volume or shell that adds `densityRate · dt` and
/// `temperatureRate · dt` to every fluid smoke cell whose centre lies inside it, and may drive the
/// air inside it (`velocity`). A plain value.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/core/SceneSpec.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/SolidLevelSet.h"

namespace modeflow {

enum class EmitterShape { Ball, Box, Mesh };

struct SmokeEmitter {
    EmitterShape shape = EmitterShape::Ball;
    Vec3 centre{0.0, 0.0, 0.0};    ///< ball
    double radius = 0.0;           ///< ball
    Vec3 min{0.0, 0.0, 0.0};       ///< box
    Vec3 max{0.0, 0.0, 0.0};       ///< box
    double densityRate = 0.0;      ///< concentration added per unit time
    double temperatureRate = 0.0;  ///< temperature added per unit time
    double fuelRate = 0.0;         ///< fuel added per unit time (a fire's: SmokeFields::fuel)
    double start = 0.0;            ///< emits while start ≤ t < end (simulated time)
    double end = std::numeric_limits<double>::infinity();
    /// mesh: its level set in world coordinates (tools/compose/MeshSolids.h builds it), and
    /// the thickness of the shell inside its surface it emits from (0: its whole volume).
    std::shared_ptr<const SolidLevelSet> levelSet = nullptr;
    double thickness = 0.0;
    /// Key frames moving it (SourceSpec::path, rotation): its centre (restCentre()) follows
    /// `path` and it turns about it. placedAt() puts it where they say at a time.
    std::vector<std::pair<double, Vec3>> path{};
    std::vector<RotationKey> rotation{};
    /// Where placedAt() put it; none: at rest, where its shape fields say.
    std::optional<ObstaclePose> placement = std::nullopt;
    /// The emitted air's velocity: while active, the velocity correction drives the fluid inside
    /// to it (SimulationSettings::velocityRegions); none: smoke and heat alone.
    std::optional<Vec3> velocity = std::nullopt;

    /// Whether the emitter emits during the step that starts at time t.
    bool activeAt(double t) const { return start <= t && t < end; }
    /// Whether key frames move it.
    bool moves() const { return !path.empty() || !rotation.empty(); }
    /// Its centre at rest: a ball's centre, a box's middle, a mesh's origin (what `path` moves).
    Vec3 restCentre() const;
    /// This emitter where its key frames put it at time t (itself when nothing moves it).
    SmokeEmitter placedAt(double t) const;
    /// Whether the point is inside (boundary included); only the first `dim` axes count (a
    /// surface's vertices: all three).
    bool contains(const Vec3& point, int dim) const;
    /// Whether the world point is inside (boundary included); only the grid's axes count, and
    /// along its periodic ones the point's image nearest the emitter's centre (an emitter on the
    /// seam fills both ends).
    bool contains(const Vec3& point, const MacGrid& grid) const;
};

/// The emitters of `all` active at time t (SmokeEmitter::activeAt), placed where they are then
/// (SmokeEmitter::placedAt).
std::vector<SmokeEmitter> activeEmitters(std::span<const SmokeEmitter> all, double t);

/// @throw modeflow::Error for more than maxSmokeEmitters emitters.
void requireEmitterCount(std::span<const SmokeEmitter> emitters);

/// The emitter of a scene's `[[source]]`; a mesh source's level set is attached afterwards
/// (attachSourceSolids).
/// @throw modeflow::Error when its shape is not a ball, a box or a mesh.
SmokeEmitter emitterFromSource(const SourceSpec& source);

/// Adds each emitter's rates · dt to the fluid cells (fluidMask ≠ 0) of `smokeGrid` whose centre
/// it contains; `density` and `temperature` hold one value per smoke cell, `fuel` as many or
/// none (no fire: the fuel rates are not applied).
void applyEmitters(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                   std::span<const SmokeEmitter> emitters, double dt, std::span<double> density,
                   std::span<double> temperature, std::span<double> fuel = {});

}  // namespace modeflow
