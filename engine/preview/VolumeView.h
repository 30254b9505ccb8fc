#pragma once
/// @file VolumeView.h
/// The camera of the 3D pictures, shared by the device renderer and its CPU reference so that
/// both march exactly the same rays: a perspective camera looking at the centre of the smoke
/// grid's box (previews: from the front right and above, azimuth −60°, elevation 25°, z up),
/// 40° of field of view across the picture's shorter side, far enough that the box's
/// circumscribed sphere fits (divided by the zoom). Units: RenderVolumeParams.h.

#include "engine/core/MacGrid.h"
#include "shaders/RenderVolumeParams.h"

namespace modeflow::preview {

/// Where the camera looks from: the previews' fixed view by default; `modeflow stir` orbits it.
struct VolumeCamera {
    double azimuthDeg = -60.0;   ///< about +z, from +x
    double elevationDeg = 25.0;  ///< above the horizontal plane
    double zoom = 1.0;           ///< > 1 moves the camera closer
    /// The ray march's step in the smallest cell size (previews: half a cell; the interactive
    /// window takes whole cells, twice as fast).
    double stepCells = 0.5;
};

/// Push constants of render_volume.comp for a width × height picture of `smokeGrid` with
/// extinction `densityScale` (optical depth across the box's largest side at density 1), the
/// density read every `densityStride` floats; the stage and item count are left for the caller.
/// @throw modeflow::Error when the grid is not 3D, the size is not positive, densityScale is
///        negative or not finite, or the zoom is not positive.
shaders::RenderVolumeParams volumeViewParams(const MacGrid& smokeGrid, int width, int height,
                                             float densityScale, const VolumeCamera& camera = {},
                                             std::uint32_t densityStride = 1);

/// `flameScale` (a flame's glow per unit t at flame 1: RenderVolumeParams.h), checked.
/// @throw modeflow::Error when it is negative or not finite.
float checkedFlameScale(float flameScale);

}  // namespace modeflow::preview
