#pragma once
/// @file VolumeReference.h
/// The CPU reference of the 3D preview (shaders/render_volume.comp, VolumeRenderer): the same
/// camera (VolumeView.h), the same light pass and ray march in the same order, in float32, so
/// the tests can hold the device to it pixel by pixel. Single-threaded and slow (seconds at
/// 512²): meant for tests and small pictures, not for previews of a run.

#include <cstdint>
#include <span>

#include "engine/core/MacGrid.h"
#include "engine/preview/Image.h"

namespace modeflow::preview {

/// A width × height picture of `density` (one float per cell of the 3D `smokeGrid`) inside
/// `fluidMask` (one byte per cell, non-zero inside Ω; cells outside are walls: no smoke, and a
/// faint glass where the mask changes). `densityScale` is the optical depth across the box's
/// largest side at density 1 (RenderVolumeParams.h); `flame` (one float per cell; empty: none)
/// glows with `flameScale` (RenderVolumeParams.h).
/// @throw modeflow::Error when the grid is not 3D, a span has the wrong size, or the size or
///        a scale is out of range (VolumeView.h).
Image renderVolumeReference(const MacGrid& smokeGrid, std::span<const float> density,
                            std::span<const std::uint8_t> fluidMask, int width, int height,
                            float densityScale, std::span<const float> flame = {},
                            float flameScale = 0.0f);

}  // namespace modeflow::preview
