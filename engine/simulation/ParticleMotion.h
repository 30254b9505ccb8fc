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
/// - then the domain: periodic axes wrap, walled ones clamp to the box, and a particle whose smoke
///   cell is not fluid (a cut-cell domain's walls) moves axis by axis, x then y then z, keeping
///   each axis's move only where it stays in the fluid (it slides along walls); an inertial one
///   loses its velocity along each axis it could not move.

#include <cmath>

#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"

namespace modeflow {

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
    double h = smokeGrid.spacing[0];
    for (int a = 1; a < smokeGrid.dim; ++a) h = std::min(h, smokeGrid.spacing[a]);
    return 1e-3 * h;
}

}  // namespace modeflow
