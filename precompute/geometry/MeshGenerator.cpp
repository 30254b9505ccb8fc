/// @file MeshGenerator.cpp
#include "precompute/geometry/MeshGenerator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <utility>

#include "engine/core/Error.h"
#include "engine/core/Vec3Math.h"

namespace modeflow {
namespace {

/// Uniform in [lo, hi) straight from the engine's bits: std::uniform_real_distribution is not
/// specified exactly, and the shipped blob must not depend on the standard library.
double uniform(std::mt19937& rng, double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(rng()) / 4294967296.0);
}

}  // namespace

TriangleMesh makeIcosphere(int subdivisions, double radius, const Vec3& center) {
    if (subdivisions < 0 || subdivisions > 8)
        throw Error("icosphere: subdivisions must be in 0..8 (got " + std::to_string(subdivisions) +
                    ")");
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> dirs = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& d : dirs) d = normalized(d);
    std::vector<std::array<int, 3>> tris = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};

    for (int level = 0; level < subdivisions; ++level) {
        // Shared edges must share their midpoint, or the mesh would not be closed.
        std::map<std::pair<int, int>, int> midpoints;
        auto midpoint = [&](int a, int b) {
            const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
            const auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            const Vec3& p = dirs[a];
            const Vec3& q = dirs[b];
            dirs.push_back(normalized({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
            const int index = static_cast<int>(dirs.size()) - 1;
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<int, 3>> finer;
        finer.reserve(tris.size() * 4);
        for (const auto& [a, b, c] : tris) {
            const int ab = midpoint(a, b);
            const int bc = midpoint(b, c);
            const int ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        tris = std::move(finer);
    }

    TriangleMesh mesh;
    mesh.vertices.reserve(dirs.size());
    for (const auto& d : dirs)
        mesh.vertices.push_back(
            {center[0] + radius * d[0], center[1] + radius * d[1], center[2] + radius * d[2]});
    mesh.triangles = std::move(tris);
    return mesh;
}

TriangleMesh makeBlobMesh(int subdivisions, unsigned seed) {
    // r(u) = 0.8 (1 + Σ a_k sin(ω_k w_k·u + φ_k)) with Σ a_k ≤ 0.2: strictly positive, so the
    // radial graph over the (closed) icosphere stays closed and free of self-intersections.
    constexpr int kWaves = 4;
    std::mt19937 rng(seed);
    std::array<Vec3, kWaves> axis{};
    std::array<double, kWaves> amplitude{}, frequency{}, phase{};
    for (int k = 0; k < kWaves; ++k) {
        Vec3 w;
        double n2 = 0.0;
        do {  // rejection sampling keeps the direction uniform on the sphere
            w = {uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
            n2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        } while (n2 > 1.0 || n2 < 1e-4);
        axis[k] = normalized(w);
        amplitude[k] = uniform(rng, 0.03, 0.05);
        frequency[k] = uniform(rng, 1.5, 3.5);  // low: a few bumps around the blob
        phase[k] = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    }

    TriangleMesh mesh = makeIcosphere(subdivisions);
    for (auto& v : mesh.vertices) {
        double scale = 1.0;
        for (int k = 0; k < kWaves; ++k) {
            const double s = v[0] * axis[k][0] + v[1] * axis[k][1] + v[2] * axis[k][2];
            scale += amplitude[k] * std::sin(frequency[k] * s + phase[k]);
        }
        for (double& x : v) x *= 0.8 * scale;
    }
    return mesh;
}

TriangleMesh makeTorus(int around, int across, double majorRadius, double minorRadius,
                       const Vec3& center) {
    if (around < 4 || around % 2 != 0 || across < 3)
        throw Error(
            "torus: an even number of at least 4 vertices around and at least 3 across (got " +
            std::to_string(around) + " and " + std::to_string(across) + ")");
    // Each ring turns half a step further than the one before, so that the triangles are nearly
    // equilateral: on an untwisted lattice the quads are isosceles trapezoids, whose diagonals
    // get cotan weights of exactly 0.
    TriangleMesh mesh;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            const double u = 2.0 * std::numbers::pi * i / around;
            const double v = 2.0 * std::numbers::pi * (j + 0.5 * i) / across;
            const double r = majorRadius + minorRadius * std::cos(v);
            mesh.vertices.push_back({center[0] + r * std::cos(u), center[1] + r * std::sin(u),
                                     center[2] + minorRadius * std::sin(v)});
        }
    // Ring `around` is ring 0 turned by around/2 steps.
    const auto at = [&](int i, int j) {
        if (i == around) return (j + around / 2) % across;
        return i * across + j % across;
    };
    // (∂p/∂u) × (∂p/∂v) points outwards: triangles run along i, then along j.
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
            mesh.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

TriangleMesh makeVoxelSurface(const std::vector<std::array<int, 3>>& voxels, int subdivisions,
                              double scale) {
    const int s = subdivisions;
    std::map<std::array<int, 3>, int> index;  // lattice point (in 1/s units) → vertex
    TriangleMesh mesh;
    std::array<int, 3> lo = voxels.front(), hi = voxels.front();
    for (const auto& v : voxels)
        for (int a = 0; a < 3; ++a)
            lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a] + 1);
    const auto vertex = [&](const std::array<int, 3>& p) {
        const auto [it, added] = index.emplace(p, int(mesh.vertices.size()));
        if (added) {
            Vec3 x;
            for (int a = 0; a < 3; ++a) x[a] = scale * (double(p[a]) / s - 0.5 * (lo[a] + hi[a]));
            mesh.vertices.push_back(x);
        }
        return it->second;
    };
    const std::set<std::array<int, 3>> solid(voxels.begin(), voxels.end());
    for (const auto& v : voxels)
        for (int a = 0; a < 3; ++a)
            for (int side : {0, 1}) {
                std::array<int, 3> neighbour = v;
                neighbour[a] += side ? 1 : -1;
                if (solid.count(neighbour)) continue;
                const int b = (a + 1) % 3, c = (a + 2) % 3;  // e_b × e_c = e_a
                for (int i = 0; i < s; ++i)
                    for (int j = 0; j < s; ++j) {
                        std::array<int, 4> q;
                        const int corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                        for (int k = 0; k < 4; ++k) {
                            std::array<int, 3> p{v[0] * s, v[1] * s, v[2] * s};
                            p[a] += side * s;
                            p[b] += i + corners[k][0];
                            p[c] += j + corners[k][1];
                            q[k] = vertex(p);
                        }
                        if (side == 1) {  // outward +e_a: counter-clockwise in (b, c)
                            mesh.triangles.push_back({q[0], q[1], q[2]});
                            mesh.triangles.push_back({q[0], q[2], q[3]});
                        } else {
                            mesh.triangles.push_back({q[0], q[2], q[1]});
                            mesh.triangles.push_back({q[0], q[3], q[2]});
                        }
                    }
            }
    return mesh;
}

TriangleMesh makeDoubleTorus(int subdivisions) {
    std::vector<std::array<int, 3>> voxels;
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 3; ++y)
            if (!(y == 1 && (x == 1 || x == 3))) voxels.push_back({x, y, 0});
    return makeVoxelSurface(voxels, subdivisions, 0.5);
}

void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh) {
    std::ofstream out(file);
    if (!out) throw Error("cannot write mesh file " + file.string());
    out << "# modeflow generated mesh: " << mesh.vertices.size() << " vertices, "
        << mesh.triangles.size() << " triangles\n";
    char line[128];
    for (const auto& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", v[0], v[1], v[2]);
        out << line;
    }
    for (const auto& [a, b, c] : mesh.triangles)
        out << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
    out.close();
    if (!out) throw Error("cannot write mesh file " + file.string());
}

void writeBlobMeshObj(const std::filesystem::path& file, int subdivisions, unsigned seed) {
    writeObj(file, makeBlobMesh(subdivisions, seed));
}

}  // namespace modeflow
