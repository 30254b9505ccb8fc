#pragma once
/// @file SolidLevelSet.h
/// A solid's shape as its depth (signed distance, positive inside) sampled on a regular lattice
/// in the solid's own frame: how a mesh obstacle (`shape = "mesh"`) covers points. Built once
/// from the mesh (tools/compose/MeshSolids.h); rigid motion moves the sample points into this
/// frame, never the lattice. The device kernel obstacle_mismatch.comp samples the same lattice
/// the same way.

#include <array>
#include <vector>

#include "engine/core/GridSpec.h"

namespace modeflow {

struct SolidLevelSet {
    Vec3 origin{0.0, 0.0, 0.0};           ///< the first sample's position
    double spacing = 1.0;                 ///< between samples along every axis
    std::array<int, 3> samples{0, 0, 0};  ///< per axis
    std::vector<float> depth;             ///< x fastest, then y, then z
    /// No point it covers lies farther than this from its frame's origin (a mesh's farthest
    /// vertex plus a lattice diagonal); 0: not known, the lattice's farthest corner bounds it.
    double radius = 0.0;

    /// The depth at `p`, trilinear between the samples; outside the lattice −spacing (outside:
    /// the lattice reaches beyond the solid on every side).
    double depthAt(const Vec3& p) const;
};

}  // namespace modeflow
