#pragma once
/// @file SurfaceImage.h
/// Pictures of a surface scene's dye (`modeflow run --preview` on a `[surface]` scene), drawn on
/// the CPU, and the stir window's picture of one: the mesh seen by a SurfaceCamera (by default a
/// fixed 3/4 view, z up, orthographic, framed on its bounding box), each pixel's dye interpolated
/// across its triangle, toned from the surface's pale grey to orange at `dyeScale`, and shaded by
/// the camera's light (by default from the upper left front).

#include <span>

#include "engine/core/TriangleMesh.h"
#include "engine/preview/Image.h"
#include "engine/preview/SurfaceCamera.h"

namespace modeflow::preview {

/// @throw modeflow::Error when `dye` does not hold one value per vertex or the size is below 8.
Image surfaceImage(const TriangleMesh& mesh, std::span<const double> dye, double dyeScale,
                   int width, int height, const SurfaceCamera& camera = {});

}  // namespace modeflow::preview
