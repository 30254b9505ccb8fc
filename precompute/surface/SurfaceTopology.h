#pragma once
/// @file SurfaceTopology.h
/// The checks a surface scene's mesh must pass, and its edges: a closed, oriented 2-manifold
/// without degenerate triangles (precompute/README.md, "Surfaces").

#include <array>
#include <string>
#include <vector>

#include "engine/core/TriangleMesh.h"

namespace modeflow {

struct SurfaceTopology {
    /// Each edge once, as (a, b) with a < b, numbered in order of first use by the triangles.
    std::vector<std::array<int, 2>> edges;
    /// The edge of each triangle's side k, which runs from corner k to corner k+1 (mod 3).
    std::vector<std::array<int, 3>> triangleEdges;
    /// +1 where side k runs from edges[e][0] to edges[e][1], −1 where it runs the other way.
    std::vector<std::array<int, 3>> triangleEdgeSigns;
    int components = 0;  ///< connected components (each a closed surface)

    int eulerCharacteristic(int vertices) const {
        return vertices - int(edges.size()) + int(triangleEdges.size());
    }
    /// β1 = Σ 2·genus over the components: the number of harmonic 1-forms.
    int harmonicCount(int vertices) const { return 2 * components - eulerCharacteristic(vertices); }
};

/// Checks `mesh`, in this order, naming the first offending element (1-based, as the OBJ file
/// numbers vertices and faces): no triangle with a repeated corner or without area; every edge
/// in exactly two triangles (closed, manifold) that run along it in opposite directions
/// (consistently oriented); every vertex in some triangle, whose triangles form a single fan
/// around it; and the triangles counter-clockwise seen from outside (a non-negative enclosed
/// volume). `name` starts every message ("mesh file scenes/meshes/torus.obj").
/// @throw Error saying what is wrong, where, and how to repair it.
SurfaceTopology checkClosedSurface(const TriangleMesh& mesh, const std::string& name);

}  // namespace modeflow
