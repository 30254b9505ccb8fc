#pragma once
/// @file ParticleMotion.h
/// How a step moves a particle, the rule both backends follow (CPU reference
/// engine/reference/ParticleAdvection.cpp, device shaders/particle_step.comp), in the velocity u
/// the step ends with (held over the step, as the smoke's advection holds it):
///
/// - a tracer (drag = 0) moves by the midpoint rule, x' = x + h u(x + ½h u(x)) (RK2: second order
///   in h), and reports that velocity;
/// - an inertial particle (drag d > 0, gravity g down the buoyancy axis ê) relaxes towards the
///   air's velocity at its midpoint predictor x + ½h v, held over the step:
///   v∞ = u(x + ½h v) − (g / d) ê, v' = v∞ + (v − v∞) e^{−dh}, x' = x + h v∞ + (v − v∞)(1 −
///   e^{−dh})/d, exact in uniform air however stiff the drag: in still air it falls at g / d;
/// - then each solid that covers x' (at the step's end) puts it `margin` past its surface
///   (SolidExit.h), and an inertial particle loses its velocity into that solid, relative to the
///   solid's material there;
/// - then the domain: a particle beyond a side the air crosses (`[grid] open`, or a wind's:
///   MacGrid::crossableSideBits) leaves the run: its position
///   becomes kParticleLeft (NaN) and its velocity 0, and it stays so, never stepped, drawn or
///   written again, its id (its place) kept by no other; otherwise periodic axes wrap, walled ones
///   clamp to the box, and a particle whose smoke cell is not fluid (a cut-cell domain's walls)
///   moves axis by axis, x then y then z, keeping each axis's move only where it stays in the
///   fluid (it slides along walls); an inertial one loses its velocity along each axis it could
///   not move.

#include <cmath>
#include <limits>

#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"

namespace modeflow {

/// The position of a particle that has left through an open side, every coordinate.
inline constexpr double kParticleLeft = std::numeric_limits<double>::quiet_NaN();

/// Whether a particle (its x, y, z position and velocity) has left through an open side: its
/// position kParticleLeft, its velocity 0 (a diverged run's values are not finite otherwise).
inline bool particleLeft(const double* position, const double* velocity) {
    return std::isnan(position[0]) && std::isnan(position[1]) && std::isnan(position[2]) &&
           velocity[0] == 0.0 && velocity[1] == 0.0 && velocity[2] == 0.0;
}

/// A set's response over one step of dt.
struct ParticleResponse {
    bool inertial = false;
    double decay = 0.0;  ///< e^{−d dt}
    double reach = 0.0;  ///< (1 − e^{−d dt}) / d
    double fall = 0.0;   ///< g / d: the speed it falls at in still air
};

inline ParticleResponse particleResponse(const ParticleSetSpec& set, double dt) {
    if (!(set.drag > 0.0)) return {};
    return {true, std::exp(-set.drag * dt), -std::expm1(-set.drag * dt) / set.drag,
            set.gravity / set.drag};
}

/// How far past a solid's surface a particle is put: a thousandth of the smoke grid's smallest
/// cell (clear of the surface at float32 too).
inline double particleExitMargin(const MacGrid& smokeGrid) {
    return 1e-3 * smokeGrid.smallestSpacing();
}

}  // namespace modeflow
