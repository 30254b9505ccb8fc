#pragma once
/// @file SolidLevelSet.h
/// A solid's shape as its depth (signed distance, positive inside) sampled on a regular lattice
/// in the solid's own frame: how a mesh obstacle (`shape = "mesh"`) covers points. Built once
/// from the mesh (tools/compose/MeshSolids.h); rigid motion moves the sample points into this
/// frame, never the lattice. A deforming mesh (a numbered sequence of files) has one per file,
/// on one lattice, each with its material's velocity. The device kernels sample the same
/// lattices the same way (shaders/ObstacleShape.glsl).

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
    /// A deforming mesh's file: the velocity of its material per sample (x, y, z; mesh units
    /// per unit time, towards the next file), and the largest |velocity|; empty: rigid.
    std::vector<float> velocity;
    double maxSpeed = 0.0;

    /// The depth at `p`, trilinear between the samples; outside the lattice −spacing (outside:
    /// the lattice reaches beyond the solid on every side).
    double depthAt(const Vec3& p) const;
    /// The same, with the depth's gradient at `p`: the trilinear interpolant's own in the
    /// lattice cell holding `p` (the same eight samples); 0 outside the lattice.
    double depthAt(const Vec3& p, Vec3& gradient) const;
    /// The material's velocity at `p`, trilinear; 0 outside the lattice or when rigid.
    Vec3 velocityAt(const Vec3& p) const;
};

}  // namespace modeflow
