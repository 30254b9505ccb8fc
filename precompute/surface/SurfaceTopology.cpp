/// @file SurfaceTopology.cpp

#include "precompute/surface/SurfaceTopology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "engine/core/Error.h"
#include "engine/core/Vec3Math.h"

namespace modeflow {
namespace {

/// A triangle as the OBJ file numbers it: "triangle 7 (vertices 3, 9, 12)".
std::string triangleText(const TriangleMesh& mesh, std::size_t t) {
    const auto& [a, b, c] = mesh.triangles[t];
    return "triangle " + std::to_string(t + 1) + " (vertices " + std::to_string(a + 1) + ", " +
           std::to_string(b + 1) + ", " + std::to_string(c + 1) + ")";
}

void requireNonDegenerate(const TriangleMesh& mesh, const std::string& name) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& [a, b, c] = mesh.triangles[t];
        if (a == b || b == c || c == a)
            throw Error(name + ": " + triangleText(mesh, t) +
                        " repeats a vertex; a surface's triangles need three distinct corners");
        const Vec3 u = sub(mesh.vertices[b], mesh.vertices[a]);
        const Vec3 v = sub(mesh.vertices[c], mesh.vertices[a]);
        const Vec3 w = sub(mesh.vertices[c], mesh.vertices[b]);
        const double longest = std::max({dot(u, u), dot(v, v), dot(w, w)});
        // Twice the area against the longest side squared: 1e-12 is an angle of about 1e-12
        // radians, far below anything a mesh means on purpose, far above round-off of zero.
        const Vec3 n = cross(u, v);
        if (!(std::sqrt(dot(n, n)) > 1e-12 * longest))
            throw Error(name + ": " + triangleText(mesh, t) +
                        " has no area (its corners are collinear or coincide); remove it or move "
                        "its corners apart");
    }
}

struct EdgeUse {
    std::vector<int> triangles;
    std::vector<int> signs;  ///< +1: the triangle runs along the edge from lower to higher vertex
};

int findRoot(std::vector<int>& parent, int i) {
    while (parent[std::size_t(i)] != i)
        i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
    return i;
}

}  // namespace

SurfaceTopology checkClosedSurface(const TriangleMesh& mesh, const std::string& name) {
    requireNonDegenerate(mesh, name);
    SurfaceTopology top;
    const std::size_t vertexCount = mesh.vertices.size();
    std::unordered_map<std::uint64_t, int> edgeIndex;
    std::vector<EdgeUse> uses;
    top.triangleEdges.resize(mesh.triangles.size());
    top.triangleEdgeSigns.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.triangles[t][std::size_t(k)],
                      b = mesh.triangles[t][std::size_t((k + 1) % 3)];
            const int lo = std::min(a, b), hi = std::max(a, b);
            const std::uint64_t key = (std::uint64_t(lo) << 32) | std::uint64_t(hi);
            const auto [it, added] = edgeIndex.emplace(key, int(top.edges.size()));
            if (added) {
                top.edges.push_back({lo, hi});
                uses.emplace_back();
            }
            const int sign = a < b ? 1 : -1;
            top.triangleEdges[t][std::size_t(k)] = it->second;
            top.triangleEdgeSigns[t][std::size_t(k)] = sign;
            uses[std::size_t(it->second)].triangles.push_back(int(t));
            uses[std::size_t(it->second)].signs.push_back(sign);
        }
    }
    for (std::size_t e = 0; e < top.edges.size(); ++e) {
        const EdgeUse& use = uses[e];
        const std::string edge = "the edge between vertices " +
                                 std::to_string(top.edges[e][0] + 1) + " and " +
                                 std::to_string(top.edges[e][1] + 1);
        if (use.triangles.size() == 1)
            throw Error(name + ": the surface is not closed: " + edge + " belongs to " +
                        triangleText(mesh, std::size_t(use.triangles[0])) +
                        " only (a hole's rim); close the hole, or check that vertices on seams are "
                        "shared, not duplicated");
        if (use.triangles.size() > 2) {
            std::string list;
            for (std::size_t i = 0; i < use.triangles.size(); ++i)
                list += (i ? ", " : "") + std::to_string(use.triangles[i] + 1);
            throw Error(name + ": the surface is not a manifold: " + edge + " is shared by " +
                        std::to_string(use.triangles.size()) + " triangles (" + list +
                        "); every edge must join exactly two");
        }
        if (use.signs[0] == use.signs[1])
            throw Error(name + ": the triangles are not consistently oriented: " +
                        triangleText(mesh, std::size_t(use.triangles[0])) + " and " +
                        triangleText(mesh, std::size_t(use.triangles[1])) + " both run along " +
                        edge +
                        " in the same direction; reverse the vertex order of one of them (every "
                        "triangle must be counter-clockwise seen from outside)");
    }

    // Each vertex's link: around a vertex v, triangle (v, x, y) leads from x to y. A single fan
    // is a single cycle of these steps.
    std::vector<std::vector<std::array<int, 2>>> link(vertexCount);
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            link[std::size_t(tri[std::size_t(k)])].push_back(
                {tri[std::size_t((k + 1) % 3)], tri[std::size_t((k + 2) % 3)]});
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const auto& steps = link[v];
        if (steps.empty())
            throw Error(name + ": vertex " + std::to_string(v + 1) +
                        " belongs to no triangle; remove it (a surface's vertices are its "
                        "triangles' corners)");
        std::unordered_map<int, int> next;
        for (const auto& [from, to] : steps) next[from] = to;
        std::size_t walked = 1;
        for (int at = next[steps[0][0]]; at != steps[0][0]; at = next[at]) ++walked;
        if (walked != steps.size())
            throw Error(name + ": vertex " + std::to_string(v + 1) +
                        " is not a manifold point: its triangles form separate fans (the surface "
                        "touches itself there); give each fan its own copy of the vertex");
    }

    std::vector<int> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& [a, b] : top.edges)
        parent[std::size_t(findRoot(parent, a))] = findRoot(parent, b);
    for (std::size_t v = 0; v < vertexCount; ++v)
        top.components += findRoot(parent, int(v)) == int(v);

    double volume = 0.0;
    for (const auto& [a, b, c] : mesh.triangles)
        volume += dot(mesh.vertices[std::size_t(a)],
                      cross(mesh.vertices[std::size_t(b)], mesh.vertices[std::size_t(c)])) /
                  6.0;
    if (volume < 0.0)
        throw Error(name +
                    ": the triangles are clockwise seen from outside (they enclose a "
                    "negative volume, " +
                    std::to_string(volume) + "); reverse the vertex order of every face");
    return top;
}

}  // namespace modeflow
