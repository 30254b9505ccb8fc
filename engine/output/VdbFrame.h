#pragma once
/// @file VdbFrame.h
/// Simulation frames as OpenVDB files (tools/README.md, "VDB frames") that Blender and Houdini open
/// as they are, and a reader of those files for tests and `--resume` checks.
///
/// One file per frame holds the grids
/// - `density`: FloatGrid, class fog volume;
/// - `temperature`: FloatGrid, class fog volume, only when the frame carries one;
/// - `fuel` and `flame`: FloatGrids, class fog volume, only with fire (`[fire]`): the unburnt
///   fuel, and the fuel burned per unit time (Blender's Principled Volume reads `flame` by name);
/// - `vel`: Vec3SGrid, vector type "contravariant relative" (a velocity: transforms with the
///   map's linear part, ignores its translation), values in world units per unit time. The MAC
///   face field is sampled at the smoke cell centres (MacSampling.h), so all grids share one
///   voxel lattice; a staggered grid would confuse both applications' renderers;
/// - `magnetic`: Vec3SGrid, only for MHD runs: the magnetic field, a face field of the basis
///   grid like the velocity (seed §6.3.5 puts it in the velocity basis), sampled and stored
///   exactly as `vel` is.
///
/// All grids share one linear transform: voxel size = the smoke grid's spacing per axis
/// (non-cubic cells give a non-uniform scale) and voxel (i, j, k)'s *centre* at the smoke cell
/// centre origin + (i+½, j+½, k+½)·h. A 2D scene becomes one voxel layer at z = 0, of depth
/// min(hx, hy), with zero z velocity.
///
/// Voxels are active only inside the fluid mask and where |value| (|vel| for the velocity)
/// reaches the activity threshold; everything else is the background 0, which keeps files
/// small and lets renderers skip empty space.
///
/// Metadata, both on the file and on every grid (importers show one or the other: Houdini turns
/// grid metadata into primitive attributes): `frame` (int32), `time` (double), `scene_hash`,
/// `modeflow_version` and `creator` = "modeflow" (strings), and for a grid with periodic axes
/// `modeflow_periodic` (vec3i: 1 where the axis x, y, z wraps, else 0): the voxels then hold one
/// period of a field that repeats along those axes, whose ends meet across the seam.
///
/// OpenVDB's types stay out of this header: VdbFrame.cpp is the one translation unit that
/// includes OpenVDB (its headers are slow to compile: tools/README.md, `build.sh`).

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "engine/core/MacGrid.h"

namespace modeflow {

/// One value per smoke cell, MacGrid::cellIndex order: float32 (a device readback) or double
/// (the CPU reference). Assigning a std::vector<float> or std::vector<double> picks the type.
using CellValues = std::variant<std::span<const float>, std::span<const double>>;

struct VdbFrameOptions {
    bool halfFloat = false;           ///< store values as 16-bit floats (about half the file size)
    double activityThreshold = 1e-4;  ///< |value| and |vel| below this stay inactive (≥ 0)
};

/// One frame to write. The spans are borrowed: they must outlive the writeVdbFrame call.
struct VdbFrame {
    MacGrid smokeGrid;                        ///< the grid of density, temperature and mask
    MacGrid basisGrid;                        ///< the grid of the face velocity
    CellValues density;                       ///< one per smoke cell (concentration)
    CellValues temperature;                   ///< one per smoke cell; empty: no temperature grid
    CellValues fuel;                          ///< one per smoke cell; empty: no fuel grid
    CellValues flame;                         ///< one per smoke cell; empty: no flame grid
    std::span<const double> faceVelocity;     ///< face field of basisGrid (MacGrid face numbering)
    std::span<const double> faceMagnetic;     ///< face field of basisGrid; empty: no magnetic grid
    std::span<const std::uint8_t> fluidMask;  ///< one per smoke cell, non-zero in Ω; empty: all
    int frame = 0;
    double time = 0.0;
    std::string sceneHash;
    std::string modeflowVersion;
    VdbFrameOptions options;
};

/// Writes `frame` to `file` atomically: into `file` + ".tmp-<pid>" in the same folder, renamed
/// over `file` once complete. On any failure the temporary file is removed and nothing appears
/// under `file` (an existing file there is left as it was).
/// @throw modeflow::Error naming `file` and the cause: the folder is missing or not writable, a
///        span has the wrong size, a value is not finite, the grids differ in dimension, the
///        threshold is negative, the grids differ in their periodic axes, OpenVDB or the file
///        system failed (disk full included).
void writeVdbFrame(const std::filesystem::path& file, const VdbFrame& frame);

/// "NAME_0001.vdb": the frame number with at least 4 digits (frame 12345 gives 5).
/// @throw modeflow::Error when `frame` is negative or `sceneName` is empty.
std::string frameFileName(std::string_view sceneName, int frame);

/// What a VDB file holds, as read back (any VDB file, not only modeflow's).
struct VdbGridInfo {
    std::string name;
    std::string gridClass;   ///< "fog volume", "level set", "staggered" or "unknown"
    std::string valueType;   ///< OpenVDB's name: "float", "vec3s", ...
    std::string vectorType;  ///< "invariant", "covariant", "contravariant relative", ...
    bool savedAsHalf = false;
    bool valuesInWorldSpace = false;  ///< vectors are world-space (not index-space) values
    std::int64_t activeVoxels = 0;
    std::optional<std::array<bool, 3>> periodic;  ///< `modeflow_periodic`; empty when absent
    Vec3 voxelSize{0.0, 0.0, 0.0};
    /// The affine part of the index-to-world map, row-vector convention as in OpenVDB:
    /// world = (i, j, k, 1) · M, M row-major.
    std::array<double, 16> indexToWorldMatrix{};

    /// World position of voxel (i, j, k)'s centre.
    Vec3 indexToWorld(double i, double j, double k) const;
};

struct VdbFrameInfo {
    std::vector<VdbGridInfo> grids;  ///< in file order
    std::optional<int> frame;        ///< file metadata; empty when absent
    std::optional<double> time;
    std::string sceneHash;  ///< empty when absent
    std::string modeflowVersion;
    std::string creator;
    std::optional<std::array<bool, 3>> periodic;  ///< `modeflow_periodic`; empty when absent

    /// The grid called `name`, nullptr when the file has none.
    const VdbGridInfo* grid(std::string_view name) const;
};

/// Reads every grid of `file` (so a truncated or corrupt frame fails here, not later).
/// @throw modeflow::Error naming the file when it is missing or not a readable VDB file.
VdbFrameInfo readVdbFrameInfo(const std::filesystem::path& file);

/// A grid's value at a point: the voxel whose centre is nearest (no interpolation, so a voxel
/// centre reads back exactly what was stored), and whether that voxel is active.
struct VdbSample {
    Vec3 value{0.0, 0.0, 0.0};  ///< scalar grids fill entry 0
    bool active = false;
};

/// Samples grid `gridName` of `file` at each world point.
/// @throw modeflow::Error when the file cannot be read, has no such grid, or the grid's value
///        type is neither float, double, vec3s nor vec3d.
std::vector<VdbSample> sampleVdbGrid(const std::filesystem::path& file, std::string_view gridName,
                                     std::span<const Vec3> worldPoints);

}  // namespace modeflow
