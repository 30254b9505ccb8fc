/// @file ClosedSurfaceCheck.cpp

#include "precompute/geometry/ClosedSurfaceCheck.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

bool degenerate(const std::array<int, 3>& t) {
    return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

std::uint64_t key(int a, int b) {
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

/// "vertices 4 and 9" of an edge, as the file numbers them.
std::string edgeName(int a, int b) {
    return "the edge between vertices " + std::to_string(a + 1) + " and " + std::to_string(b + 1);
}

std::string triangleName(std::size_t t) {
    return "triangle " + std::to_string(t + 1);
}

struct EdgeUse {
    int count = 0;
    std::size_t first = 0;  ///< the first triangle using it
};

}  // namespace

void requireClosedSurface(const TriangleMesh& mesh, const std::filesystem::path& file) {
    const std::string name = "mesh file " + file.string();
    std::unordered_map<std::uint64_t, EdgeUse> undirected;
    std::unordered_map<std::uint64_t, std::size_t> directed;  // a → b: the triangle running it
    struct Flip {
        std::size_t first, second;
        int a, b;
    };
    std::optional<Flip> flipped;  // the first edge two triangles run the same way
    undirected.reserve(mesh.triangles.size() * 2);
    directed.reserve(mesh.triangles.size() * 4);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& triangle = mesh.triangles[t];
        if (degenerate(triangle)) continue;
        for (int k = 0; k < 3; ++k) {
            const int a = triangle[k], b = triangle[(k + 1) % 3];
            EdgeUse& use = undirected[key(std::min(a, b), std::max(a, b))];
            if (use.count++ == 0) use.first = t;
            const auto [at, inserted] = directed.emplace(key(a, b), t);
            if (!inserted && !flipped) flipped = Flip{at->second, t, a, b};
        }
    }
    // The first triangle (in file order) with an edge that is not shared by exactly two.
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& triangle = mesh.triangles[t];
        if (degenerate(triangle)) continue;
        for (int k = 0; k < 3; ++k) {
            const int a = std::min(triangle[k], triangle[(k + 1) % 3]);
            const int b = std::max(triangle[k], triangle[(k + 1) % 3]);
            const EdgeUse& use = undirected.at(key(a, b));
            if (use.count == 1)
                throw Error(name + " is not a closed surface: " + edgeName(a, b) + " of " +
                            triangleName(t) +
                            " belongs to no other triangle (the mesh is open there; vertices are "
                            "matched by index, so duplicated vertices leave seams open)");
            if (use.count > 2)
                throw Error(name + " is not a closed surface: " + edgeName(a, b) + " of " +
                            triangleName(t) + " is shared by " + std::to_string(use.count) +
                            " triangles (non-manifold: every edge must join exactly two)");
        }
    }
    if (flipped)
        throw Error(name + " is not consistently oriented: " + triangleName(flipped->first) +
                    " and " + triangleName(flipped->second) + " both run " +
                    edgeName(flipped->a, flipped->b) + " from " + std::to_string(flipped->a + 1) +
                    " to " + std::to_string(flipped->b + 1) +
                    ", so one of them is flipped; every triangle must be counter-clockwise seen "
                    "from outside");
    // The enclosed volume by the divergence theorem: Σ a · (b × c) / 6, positive when the
    // triangles face out.
    double volume = 0.0;
    for (const auto& triangle : mesh.triangles) {
        if (degenerate(triangle)) continue;
        const Vec3 &a = mesh.vertices[std::size_t(triangle[0])],
                   &b = mesh.vertices[std::size_t(triangle[1])],
                   &c = mesh.vertices[std::size_t(triangle[2])];
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0])) /
                  6.0;
    }
    if (volume < 0.0) {
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.3g", volume);
        throw Error(name +
                    " is inside out: its triangles are clockwise seen from outside (the "
                    "volume they enclose is " +
                    std::string(shown) + "); reverse every face's vertex order");
    }
}

}  // namespace modeflow
