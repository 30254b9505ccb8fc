#pragma once
/// @file SceneLoader.h
/// Reads a scene file (scenes/README.md, "Scene files") into a validated SceneSpec. Everything a
/// user can get wrong in a scene is caught here, with a message that names the file and the key, so
/// later stages can trust the values they are given. The TOML library stays inside
/// precompute/scene.

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/SceneKeywords.h"
#include "engine/core/SceneSpec.h"

namespace modeflow {

/// Largest accepted scene file, 4 MiB: a hand-written scene is a few kilobytes, a generated one
/// with long key-frame paths well under a megabyte. Checked before reading (parsing costs about
/// 40 bytes of memory per byte of file), like the file's kind: a device or a FIFO is refused.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{4} << 20;
/// Most '.' characters on one line of a scene file. Each dot of a key nests a table, and toml++
/// walks nested tables recursively: 100000 of them overflowed the stack. Three lines can add up
/// to one nesting (a [table.header], a dotted.key = [ and an inline {table} inside the array),
/// about 12000 tables, well within the stack; floats count too, so a long array of them may
/// need to be spread over several lines.
inline constexpr int kMaxDotsPerLine = 4096;
/// Largest accepted entry of `[grid].resolution`.
inline constexpr int kMaxGridResolution = 4096;
/// Accepted cell sizes ((bounds_max - bounds_min) / resolution on each axis), in scene units. The
/// solver is scale-free well beyond them (it fails near 1e±100), but no scene needs more, and
/// within them every derived quantity (cell volume, face area, 1/h²) is a normal double.
inline constexpr double kMinCellSize = 1e-6;
inline constexpr double kMaxCellSize = 1e6;
/// Largest accepted ratio between the cell sizes of two axes: cells stretched further resolve
/// nothing along their long side.
inline constexpr double kMaxCellAspectRatio = 1e3;
/// Farthest a grid bound may lie from the origin, in cells of that axis: at 1e12 cells a
/// coordinate rounds by 2e-4 of a cell (relative precision 2^-52), and much farther out cells
/// shrink to nothing in floating point.
inline constexpr double kMaxCellsFromOrigin = 1e12;
/// Largest accepted initial speed, in scene units per unit of time, as [initial] sets it: the mean
/// speed sqrt(2 energy / grid volume) of `energy` or of the modal amplitudes, the mean field of
/// `magnetic_energy`, `magnetic_strength`, and a vortex's strength over the grid's longest side.
/// Example scenes use about 1; 1e300 overflowed the squares of the dynamics into "energy = inf".
/// A source's `velocity` is held to the same limit (a jet of 1e300 blew up the first step).
inline constexpr double kMaxInitialSpeed = 1e6;
/// Largest accepted magnitude of a smoke value a scene sets: a source's or the wind's `density`,
/// `temperature`, `fuel`, and `[fire]` `ignition`, `heat`, `smoke`. The device holds the smoke in
/// 32-bit floats: a source of density 1e300 ran into infinity in the frames.
inline constexpr double kMaxSmokeValue = 1e6;
/// Largest accepted `sequence_rate` of a deforming mesh obstacle, files per unit of time.
inline constexpr double kMaxSequenceRate = 1e6;
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

/// The integrator a scene keyword names ("explicit", "rk4", "midpoint", "trapezoidal",
/// "linearized"), for
/// command-line options that override [simulation].integrator. `key` prefixes the message.
/// @throw Error naming the value, the closest keyword and the choices.
Integrator parseIntegrator(std::string_view text, std::string_view key);

}  // namespace modeflow
