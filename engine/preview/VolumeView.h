#pragma once
/// @file VolumeView.h
/// The fixed camera of the 3D previews, shared by the device renderer and its CPU reference so
/// that both march exactly the same rays: a perspective camera looking at the centre of the
/// smoke grid's box from the front right and above (azimuth −60°, elevation 25°, z up), 40° of
/// field of view across the picture's shorter side, far enough that the box's circumscribed
/// sphere fits. Rays are marched every half of the smallest cell. Units: RenderVolumeParams.h.

#include "engine/field/MacGrid.h"
#include "shaders/RenderVolumeParams.h"

namespace modeflow::preview {

/// Push constants of render_volume.comp for a width × height picture of `smokeGrid` with
/// extinction `densityScale` (optical depth across the box's largest side at density 1); the
/// stage and item count are left for the caller.
/// @throw modeflow::Error when the grid is not 3D, the size is not positive, or densityScale
///        is negative or not finite.
shaders::RenderVolumeParams volumeViewParams(const MacGrid& smokeGrid, int width, int height,
                                             float densityScale);

}  // namespace modeflow::preview
