#pragma once
/// @file TriangleMesh.h
/// An indexed triangle mesh: the shape of a mesh domain, and the surface a surface scene's fluid
/// lives on (its cache keeps it for the runtime's dye and frames). A plain value.

#include <array>
#include <vector>

#include "engine/core/GridSpec.h"

namespace modeflow {

/// Triangles are counter-clockwise seen from outside.
struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;  ///< 0-based vertex indices
    bool operator==(const TriangleMesh&) const = default;
};

}  // namespace modeflow
