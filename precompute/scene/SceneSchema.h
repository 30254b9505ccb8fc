#pragma once
/// @file SceneSchema.h
/// Internal to precompute/scene: what a scene file may hold. The spelling of every choice (keyword
/// ↔ enum tables) and the keys each table takes, so that a key is checked before it is read and
/// a typo is never silently replaced by a default.

#include <span>
#include <string_view>
#include <utility>

#include "engine/core/SceneKeywords.h"
#include "engine/core/SceneSpec.h"

namespace modeflow::scene {

using keywords::Choices;
using keywords::keywordOf;
using namespace keywords;

inline constexpr std::string_view kTopLevelTables[] = {
    "grid",      "domain", "surface", "basis", "simulation", "initial", "source", "obstacle",
    "particles", "smoke",  "fire",    "wind",  "inflow",     "forcing", "output"};
inline constexpr std::string_view kGridKeys[] = {"resolution", "bounds_min", "bounds_max",
                                                 "periodic", "open"};
inline constexpr std::string_view kSurfaceKeys[] = {"mesh"};
/// [basis] keys that only a grid scene takes.
inline constexpr std::string_view kGridBasisKeys[] = {"scalar_boundary", "wall", "boundary",
                                                      "subsamples", "eigensolver"};
inline constexpr std::string_view kBasisKeys[] = {"velocity_modes",  "modes",        "scalar_modes",
                                                  "scalar_boundary", "wall",         "boundary",
                                                  "subsamples",      "coefficients", "eigensolver"};
inline constexpr std::string_view kSimulationKeys[] = {
    "dt", "integrator", "viscosity", "alpha", "mhd", "magnetic_diffusivity", "basis_precision"};
inline constexpr std::string_view kInitialKeys[] = {"velocity",
                                                    "energy",
                                                    "seed",
                                                    "band",
                                                    "amplitudes",
                                                    "vortex",
                                                    "magnetic",
                                                    "magnetic_energy",
                                                    "magnetic_seed",
                                                    "magnetic_direction",
                                                    "magnetic_strength",
                                                    "magnetic_wall_layer"};
/// [initial] keys of the magnetic field (MHD only), which go with any velocity choice.
inline constexpr std::string_view kInitialFieldKeys[] = {
    "magnetic",           "magnetic_energy",   "magnetic_seed",
    "magnetic_direction", "magnetic_strength", "magnetic_wall_layer"};
inline constexpr std::string_view kVortexKeys2d[] = {"center", "strength", "radius"};
inline constexpr std::string_view kVortexKeys3d[] = {"center", "normal", "ring_radius", "radius",
                                                     "strength"};
inline constexpr std::string_view kObstacleKeys[] = {
    "shape", "radius", "half_size", "axis", "file", "scale", "path", "sequence_rate", "rotation"};
inline constexpr std::string_view kSmokeKeys[] = {"buoyancy", "resolution_scale", "advection"};
inline constexpr std::string_view kFireKeys[] = {"ignition", "burn_rate", "heat", "smoke"};
inline constexpr std::string_view kWindKeys[] = {"velocity", "profile", "thickness",
                                                 "exponent", "density", "temperature"};
inline constexpr std::string_view kForcingKeys[] = {"hold_modes", "hold_below_kappa"};
inline constexpr std::string_view kOutputKeys[] = {"frames", "steps_per_frame"};
inline constexpr std::string_view kSourceExtraKeys[] = {
    "density", "temperature", "fuel", "start", "end", "velocity", "thickness", "path", "rotation"};

inline constexpr std::string_view kInflowExtraKeys[] = {
    "side", "velocity", "density", "temperature", "fuel", "start", "end"};
inline constexpr std::string_view kParticleExtraKeys[] = {"count", "rate",    "start", "end",
                                                          "drag",  "gravity", "seed"};

/// The `[initial]` keys each velocity choice reads besides `velocity`.
std::span<const std::string_view> initialKeys(InitialVelocity velocity);

/// The `[initial]` keys each magnetic field choice reads besides `magnetic`.
std::span<const std::string_view> magneticKeys(InitialMagnetic magnetic);

/// The keys each shape takes besides `shape` (and `op` in `[[domain]]`).
std::span<const std::string_view> shapeKeys(ShapeKind kind);

}  // namespace modeflow::scene
