#pragma once
/// @file DeformingSolids.h
/// A deforming mesh obstacle (`file = "flag_####.obj"`, `sequence_rate`): one level set per file
/// the run reaches, all on one lattice, each holding its material's velocity towards the next
/// file — by vertex correspondence when both files have as many vertices (the vertices' own
/// motion, spread to the samples by inverse-distance weights of the vertices around them), else
/// from the level sets' motion (−∂d/∂t ∇d / |∇d|², normal to the surface: tangential motion is
/// lost). The last file moves towards the one after it when the folder has it, else holds still.

#include <cstddef>
#include <memory>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "engine/simulation/SolidLevelSet.h"

namespace modeflow {

/// The level sets of the scene's obstacle `index` (a mesh with a sequence_rate), file by file,
/// sampled every `spacing` world lengths: files 1 to floor(T · rate) + 1, T the run's end
/// (frames × steps_per_frame × dt; `run --frames` sets the scene's frames first).
/// @throw modeflow::Error naming the obstacle and the first file the run needs that is missing,
///        a file that is not a closed, consistently oriented, outward-facing surface, or files
///        that together would take more than 2^25 samples.
std::vector<std::shared_ptr<const SolidLevelSet>> deformingSolids(const SceneSpec& scene,
                                                                  std::size_t index,
                                                                  double spacing);

}  // namespace modeflow
