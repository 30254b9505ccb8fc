#pragma once
/// @file SceneLoader.h
/// Reads a scene file (DESIGN §5) into a validated SceneSpec. Everything a user can get wrong in a
/// scene is caught here, with a message that names the file and the key, so later stages can trust
/// the values they are given. The TOML library stays inside SceneLoader.cpp.

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/SceneSpec.h"

namespace modeflow {

/// Largest accepted entry of `[grid].resolution`.
inline constexpr int kMaxGridResolution = 4096;
/// Largest accepted cell count of the basis grid (2^27): beyond it no eigensolve finishes anyway.
inline constexpr std::int64_t kMaxGridCells = std::int64_t{1} << 27;
/// Largest accepted cell count of the smoke grid (basis grid refined by `resolution_scale`).
inline constexpr std::int64_t kMaxSmokeCells = std::int64_t{1} << 31;

/// Reads and validates a scene file. SceneSpec::name is the file's stem, SceneSpec::sourceFile the
/// path as given. Relative mesh paths are resolved against the file's folder.
/// 2D grids get resolution[2] = 1 and keep the default [0, 1] bounds on the third axis, so products
/// of spacings give areas; 2D vectors (centres, box corners) get a third entry of 0.
/// @throw Error whose message starts with the file name and names the offending key, e.g.
/// "scenes/x.toml: [grid].resolution: expected 2 or 3 integers, got 4 entries (line 2)"
SceneSpec loadScene(const std::filesystem::path& file);

/// Same as loadScene, from text already in memory. `origin` is used in messages, gives the scene
/// its name, and its parent folder resolves relative mesh paths.
SceneSpec parseScene(std::string_view text, const std::filesystem::path& origin);

/// Parses a mode list such as "1-115,516-630" or "40" (1-based, inclusive; a lone number is that
/// single mode). Ranges must be sorted and disjoint. `key` prefixes error messages.
/// @throw Error on bad syntax, overlapping/unsorted ranges, first > last or first < 1.
std::vector<ModeRange> parseModeRanges(std::string_view text, std::string_view key);

/// The scene-file spelling of each choice ("ball", "subtract", "free-slip", "rk4", ...), for
/// summaries and messages that should read like the file.
std::string_view sceneKeyword(ShapeKind kind);
std::string_view sceneKeyword(CsgOp op);
std::string_view sceneKeyword(ScalarBoundary boundary);
std::string_view sceneKeyword(WallKind wall);
std::string_view sceneKeyword(BoundaryTreatment treatment);
std::string_view sceneKeyword(Integrator integrator);

/// The integrator a scene keyword names ("explicit", "rk4", "midpoint", "trapezoidal"), for
/// command-line options that override [simulation].integrator. `key` prefixes the message.
/// @throw Error naming the value, the closest keyword and the choices.
Integrator parseIntegrator(std::string_view text, std::string_view key);
std::string_view sceneKeyword(InitialVelocity velocity);

}  // namespace modeflow
