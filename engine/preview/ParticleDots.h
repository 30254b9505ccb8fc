#pragma once
/// @file ParticleDots.h
/// Particles drawn over a picture of the smoke (previews; `modeflow stir` draws its own on the
/// device): a dot of about three pixels per particle in Palette.h's kParticle, over the smoke,
/// placed by the picture's own mapping (a 2D grid's pixel blocks, a 3D view's camera).

#include <span>

#include "engine/core/MacGrid.h"
#include "engine/preview/Image.h"
#include "shaders/RenderVolumeParams.h"

namespace modeflow::preview {

/// Over renderSmoke2D's picture of `smokeGrid` at `pixelsPerCell`.
void drawParticles2D(Image& picture, const MacGrid& smokeGrid, int pixelsPerCell,
                     std::span<const double> positions);

/// Over a 3D picture of `smokeGrid` seen by `view` (volumeViewParams). Points behind the camera
/// are not drawn.
void drawParticles3D(Image& picture, const MacGrid& smokeGrid,
                     const shaders::RenderVolumeParams& view, std::span<const double> positions);

}  // namespace modeflow::preview
