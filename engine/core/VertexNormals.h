#pragma once
/// @file VertexNormals.h
/// The unit normal at each vertex of a closed triangle mesh: its triangles' area-weighted
/// normals, outwards (triangles counter-clockwise seen from outside). What a stirring splat's
/// force is turned into the tangent plane with, on either backend.

#include <vector>

#include "engine/core/TriangleMesh.h"

namespace modeflow {

/// One unit normal per vertex; zero for a vertex in no triangle.
std::vector<Vec3> vertexNormals(const TriangleMesh& mesh);

}  // namespace modeflow
