#pragma once
/// @file ClosedSurfaceCheck.h
/// What makes a triangle mesh a solid's surface: closed (every edge joins exactly two
/// triangles), consistently oriented (neighbours run their shared edge in opposite directions)
/// and facing out (counter-clockwise seen from outside: positive enclosed volume). Mesh domains
/// and mesh obstacles are refused otherwise, naming the first offending edge or triangle.

#include <filesystem>

#include "engine/core/TriangleMesh.h"

namespace modeflow {

/// Triangles with a repeated vertex (no area) are left out of every check. Vertices and
/// triangles are named 1-based, vertices as the OBJ file numbers them, triangles in the order
/// the file's faces give them (a polygon counts as its fan of triangles).
/// @throw Error naming `file` and the first edge used by one triangle (open) or by more than
///        two (non-manifold), or the first pair of triangles running an edge the same way
///        (inconsistent orientation), or the mesh's negative volume (inside out).
void requireClosedSurface(const TriangleMesh& mesh, const std::filesystem::path& file);

}  // namespace modeflow
