/// @file MeshLevelSetTest.cpp
/// Mesh shapes: OBJ files written at test time (quad cube, icosphere, blob, broken files) are
/// turned into level sets; signs, distances within a voxel, concurrency and error messages.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/Error.h"
#include "precompute/geometry/ImplicitShape.h"
#include "precompute/geometry/MeshGenerator.h"
#include "precompute/geometry/MeshLevelSet.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

class MeshLevelSetTest : public ::testing::Test {
protected:
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path file = mDir / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    testing::TestFolder mFolder;
    const fs::path mDir = mFolder.path();
};

/// The cube [-h, h]³ as six quads (outward normals); `skipTop` leaves the +z face out.
std::string cubeObj(double h, bool skipTop = false) {
    std::ostringstream s;
    for (int i = 0; i < 8; ++i)
        s << "v " << (i & 1 ? h : -h) << ' ' << (i & 2 ? h : -h) << ' ' << (i & 4 ? h : -h) << '\n';
    // Vertex i = (x bit 0, y bit 1, z bit 2), 1-based in the file.
    s << "f 1 3 4 2\n"                 // z = -h
      << "f 1 2 6 5\n"                 // y = -h
      << "f 1 5 7 3\n"                 // x = -h
      << "f 2 4 8 6\n"                 // x = +h
      << "f 3 7 8 4\n";                // y = +h
    if (!skipTop) s << "f 5 6 8 7\n";  // z = +h
    return s.str();
}

double cubeSdf(const Vec3& p, double h) {  // positive inside
    double outside2 = 0.0, inside = -1e300;
    for (double x : p) {
        const double q = std::abs(x) - h;
        if (q > 0) outside2 += q * q;
        inside = std::max(inside, q);
    }
    return outside2 > 0 ? -std::sqrt(outside2) : -inside;
}

std::string expectMeshError(const fs::path& file, double voxel = 0.05) {
    try {
        loadMeshShape(file, voxel);
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos)
            << "the message must name the file: " << what;
        return what;
    }
    ADD_FAILURE() << "no error for " << file;
    return {};
}

TEST_F(MeshLevelSetTest, CubeSignsAndDistances) {
    const double h = 0.5, voxel = 0.05;
    const auto shape = loadMeshShape(write("cube.obj", cubeObj(h)), voxel);
    const double band = 3 * voxel;
    EXPECT_NEAR(shape->value({0, 0, 0}), band, 1e-6);     // deep inside: +background
    EXPECT_NEAR(shape->value({2, 0, 0}), -band, 1e-6);    // far outside: -background
    EXPECT_NEAR(shape->value({50, 9, -3}), -band, 1e-6);  // beyond the grid entirely

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    int near = 0;
    for (int k = 0; k < 20000; ++k) {
        const Vec3 p{u(rng), u(rng), u(rng)};
        const double truth = cubeSdf(p, h);
        const double v = shape->value(p);
        // Never more than the distance (up to the float storage and one voxel of band edge).
        EXPECT_LE(std::abs(v), std::abs(truth) + voxel);
        if (std::abs(truth) > voxel) {
            EXPECT_EQ(v > 0, truth > 0) << p[0] << ' ' << p[1] << ' ' << p[2];
        }
        if (std::abs(truth) < band - voxel) {
            ++near;
            EXPECT_NEAR(v, truth, voxel) << p[0] << ' ' << p[1] << ' ' << p[2];
        }
    }
    EXPECT_GT(near, 1000);
}

TEST_F(MeshLevelSetTest, IcosphereDistancesWithinAVoxel) {
    const Vec3 c{0.1, -0.05, 0.2};
    const double r = 0.6, voxel = 0.04;
    const fs::path file = mDir / "sphere.obj";
    writeObj(file, makeIcosphere(4, r, c));
    const auto shape = loadMeshShape(file, voxel, 4.0);
    std::mt19937 rng(9);
    std::normal_distribution<double> g(0.0, 1.0);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (int k = 0; k < 5000; ++k) {
        Vec3 d{g(rng), g(rng), g(rng)};
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double rad = r + u(rng);
        const Vec3 p{c[0] + rad * d[0] / n, c[1] + rad * d[1] / n, c[2] + rad * d[2] / n};
        EXPECT_NEAR(shape->value(p), r - rad, voxel);
        if (std::abs(r - rad) > voxel) {
            EXPECT_EQ(shape->value(p) > 0, rad < r);
        }
    }
    EXPECT_GT(shape->value(c), 0.0);
    EXPECT_LT(shape->value({c[0], c[1], c[2] + 1.5}), 0.0);
}

TEST_F(MeshLevelSetTest, MakeShapeLoadsMeshes) {
    ShapeSpec spec;
    spec.kind = ShapeKind::Mesh;
    spec.meshFile = write("cube.obj", cubeObj(0.5));
    const auto shape = makeShape(spec, 3, 0.05);
    EXPECT_GT(shape->value({0.45, 0, 0}), 0.0);
    EXPECT_LT(shape->value({0.55, 0, 0}), 0.0);
    EXPECT_THROW(makeShape(spec, 2, 0.05), Error);
}

TEST_F(MeshLevelSetTest, ConcurrentQueriesMatchSerialOnes) {
    const fs::path file = mDir / "blob.obj";
    writeBlobMeshObj(file, 3, 5);
    const auto shape = loadMeshShape(file, 0.03);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-1.1, 1.1);
    std::vector<Vec3> points(40000);
    for (auto& p : points) p = {u(rng), u(rng), u(rng)};
    std::vector<double> serial(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) serial[i] = shape->value(points[i]);

    const int threads = 6;
    std::vector<std::vector<double>> results(threads, std::vector<double>(points.size()));
    {
        std::vector<std::jthread> pool;
        for (int t = 0; t < threads; ++t)
            pool.emplace_back([&, t] {
                // Each thread walks the points in its own order so that they interleave: strides
                // coprime to the point count make each walk a permutation.
                constexpr std::size_t strides[] = {1, 3, 7, 11, 13, 17};
                for (std::size_t k = 0; k < points.size(); ++k) {
                    const std::size_t i = (k * strides[t] + 977 * t) % points.size();
                    results[t][i] = shape->value(points[i]);
                }
            });
    }
    for (int t = 0; t < threads; ++t) EXPECT_EQ(results[t], serial) << "thread " << t;
}

TEST_F(MeshLevelSetTest, GeneratedBlobIsClosedAndStarShaped) {
    const TriangleMesh blob = makeBlobMesh(3, 11);
    EXPECT_EQ(blob.vertices.size(), 10u * 64 + 2);
    EXPECT_EQ(blob.triangles.size(), 20u * 64);
    double volume = 0.0;  // positive: triangles are counter-clockwise seen from outside
    for (const auto& [a, b, c] : blob.triangles) {
        const Vec3& p = blob.vertices[a];
        const Vec3& q = blob.vertices[b];
        const Vec3& r = blob.vertices[c];
        volume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                   p[2] * (q[0] * r[1] - q[1] * r[0])) /
                  6.0;
    }
    EXPECT_GT(volume, 4.0 / 3.0 * std::numbers::pi * 0.62 * 0.62 * 0.62);
    EXPECT_LT(volume, 4.0 / 3.0 * std::numbers::pi * 0.98 * 0.98 * 0.98);
    double rmin = 1e9, rmax = 0;
    for (const auto& v : blob.vertices) {
        const double rad = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        rmin = std::min(rmin, rad);
        rmax = std::max(rmax, rad);
    }
    EXPECT_GE(rmin, 0.62);
    EXPECT_LE(rmax, 0.98);
    EXPECT_GT(rmax - rmin, 0.05) << "the blob should be visibly irregular";

    const fs::path file = mDir / "blob.obj";
    writeBlobMeshObj(file, 3, 11);
    const auto shape = loadMeshShape(file, 0.03);  // throws if it were open
    EXPECT_GT(shape->value({0, 0, 0}), 0.0);
    EXPECT_LT(shape->value({0, 0, 1.1}), 0.0);
    EXPECT_LT(shape->value({-1.05, 0, 0}), 0.0);

    // Trilinear interpolation is only nearly 1-Lipschitz (about 1.1 measured on blobs).
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-1.1, 1.1);
    std::normal_distribution<double> g(0.0, 1.0);
    double worst = 0.0;
    for (int k = 0; k < 50000; ++k) {
        const Vec3 a{u(rng), u(rng), u(rng)};
        const double scale = k % 2 ? 0.003 : 0.03;
        const Vec3 b{a[0] + scale * g(rng), a[1] + scale * g(rng), a[2] + scale * g(rng)};
        const double d = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                   (a[2] - b[2]) * (a[2] - b[2]));
        worst = std::max(worst, std::abs(shape->value(a) - shape->value(b)) / d);
    }
    EXPECT_LT(worst, 1.25);
}

TEST_F(MeshLevelSetTest, ShippedBlobMatchesTheGenerator) {
    // scenes/meshes/blob.obj = writeBlobMeshObj(path, 4, 1); regenerating must give it back.
    const fs::path shipped = fs::path(MODEFLOW_SOURCE_DIR) / "scenes" / "meshes" / "blob.obj";
    ASSERT_TRUE(fs::exists(shipped)) << shipped;
    EXPECT_LT(fs::file_size(shipped), 300u * 1024);
    const TriangleMesh expected = makeBlobMesh(4, 1);
    std::ifstream in(shipped);
    std::string line;
    std::size_t v = 0, f = 0;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            ASSERT_LT(v, expected.vertices.size());
            double x, y, z;
            s >> x >> y >> z;
            EXPECT_NEAR(x, expected.vertices[v][0], 2e-6);
            EXPECT_NEAR(y, expected.vertices[v][1], 2e-6);
            EXPECT_NEAR(z, expected.vertices[v][2], 2e-6);
            ++v;
        } else if (tag == "f") {
            ASSERT_LT(f, expected.triangles.size());
            int a, b, c;
            s >> a >> b >> c;
            EXPECT_EQ(a - 1, expected.triangles[f][0]);
            EXPECT_EQ(b - 1, expected.triangles[f][1]);
            EXPECT_EQ(c - 1, expected.triangles[f][2]);
            ++f;
        }
    }
    EXPECT_EQ(v, expected.vertices.size());
    EXPECT_EQ(f, expected.triangles.size());
    const auto shape = loadMeshShape(shipped, 0.05);
    EXPECT_GT(shape->value({0, 0, 0}), 0.0);
    EXPECT_LT(shape->value({1, 1, 1}), 0.0);
}

TEST_F(MeshLevelSetTest, MissingFileIsReported) {
    const std::string what = expectMeshError(mDir / "nope" / "missing.obj");
    EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, DirectoryIsReported) {
    const std::string what = expectMeshError(mDir);
    EXPECT_NE(what.find("is a directory, not a regular file"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, GarbageFileIsReported) {
    std::string garbage = "PK\x03\x04 this is not an OBJ\nrandom words here\n{\"json\": true}\n";
    for (int i = 0; i < 256; ++i) garbage += static_cast<char>((i * 37) % 256);
    const std::string what = expectMeshError(write("garbage.obj", garbage));
    EXPECT_TRUE(what.find("not a valid OBJ") != std::string::npos ||
                what.find("no faces") != std::string::npos)
        << what;
}

TEST_F(MeshLevelSetTest, EmptyAndFacelessFilesAreReported) {
    std::string what = expectMeshError(write("empty.obj", ""));
    EXPECT_NE(what.find("no faces"), std::string::npos) << what;
    what = expectMeshError(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"));
    EXPECT_NE(what.find("no faces"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, BadFaceIndexIsReported) {
    expectMeshError(write("badindex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"));
}

/// cubeObj(0.5) with its line `line` (1-based) replaced.
std::string cubeWithLine(int line, const std::string& text) {
    std::istringstream in(cubeObj(0.5));
    std::string out, current;
    for (int n = 1; std::getline(in, current); ++n) out += (n == line ? text : current) + "\n";
    return out;
}

TEST_F(MeshLevelSetTest, UnreadableVertexCoordinatesAreRefusedWithTheirLine) {
    // tinyobjloader reads each of these as 0: the mesh loses a corner without a word.
    const std::pair<std::string, std::string> cases[] = {
        {"v nan 0.5 0.5", "coordinate nan is not finite"},
        {"v 0.5 abc 0.5", "coordinate \"abc\" is not a number"},
        {"v 0.5 0.5 -inf", "coordinate -inf is not finite"},
        {"v 1e39 0.5 0.5", "coordinate 1e39 is beyond the float range"},
        {"v 0.5 0.5 0.5x", "coordinate \"0.5x\" is not a number"},
        {"v 0.5 0.5", "has 2 coordinates, expected 3"},
        {"v 0.5 \x01\x1b[2J 0.5", "coordinate \"\\x01\\x1b[2J\" is not a number"},
    };
    for (const auto& [line, problem] : cases) {
        const std::string what = expectMeshError(write("bad.obj", cubeWithLine(7, line)));
        EXPECT_NE(what.find(", line 7: vertex 7 " + problem), std::string::npos) << what;
    }
    // Vertex colours and a fourth (w) coordinate are not coordinates of the position.
    EXPECT_NO_THROW(
        loadMeshShape(write("colours.obj", cubeWithLine(7, "v 0.5 0.5 0.5 1 0 0")), 0.05));
}

TEST_F(MeshLevelSetTest, FacesReferringToMissingVerticesNameTheirLine) {
    const std::pair<std::string, std::string> cases[] = {
        {"f 5 6 8 9", "line 14: a face refers to vertex 9, but the file has 8 vertices"},
        {"f 5 6 0 7", "line 14: a face refers to vertex 0 (vertices are numbered from 1)"},
        {"f -9 6 8 7",
         "line 14: a face refers to vertex -9 (relative), but only 8 vertices precede it"},
        {"f 5 6 x/1 7", "line 14: a face refers to vertex \"x/1\", which is not a vertex number"},
    };
    for (const auto& [line, problem] : cases) {
        const std::string what = expectMeshError(write("bad.obj", cubeWithLine(14, line)));
        EXPECT_NE(what.find(problem), std::string::npos) << what;
    }
    // Texture and normal indices after the vertex's own are allowed; relative indices count back.
    EXPECT_NO_THROW(
        loadMeshShape(write("relative.obj", cubeWithLine(14, "f -4/1/1 -3//2 -1 -2")), 0.05));
}

TEST_F(MeshLevelSetTest, OpenMeshIsRejected) {
    const std::string what = expectMeshError(write("open.obj", cubeObj(0.5, true)));
    EXPECT_NE(what.find("not a closed surface"), std::string::npos) << what;
    EXPECT_NE(what.find("belongs to no other triangle (the mesh is open there"), std::string::npos)
        << what;
    EXPECT_NE(what.find("the edge between vertices "), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, NonManifoldMeshIsRejected) {
    // Two closed tetrahedra sharing the edge 1–2: that edge joins four triangles.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nv 0 0 -1\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
        "f 1 2 5\nf 1 6 2\nf 1 5 6\nf 2 6 5\n";
    const std::string what = expectMeshError(write("bowtie.obj", text));
    EXPECT_NE(what.find("the edge between vertices 1 and 2 of triangle 1 is shared by 4 triangles"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find("open"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, InsideOutMeshIsRejected) {
    // A tetrahedron whose triangles are all clockwise seen from outside.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
    const std::string what = expectMeshError(write("inverted.obj", text));
    EXPECT_NE(what.find("is inside out"), std::string::npos) << what;
    EXPECT_NE(what.find("-0.167"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, AFlippedTriangleIsNamed) {
    // The outward tetrahedron with its third triangle flipped.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 3 4\nf 2 3 4\n";
    const std::string what = expectMeshError(write("flipped.obj", text));
    EXPECT_NE(what.find("is not consistently oriented: triangle 1 and triangle 3 both run the edge "
                        "between vertices 1 and 3 from 1 to 3"),
              std::string::npos)
        << what;
}

TEST_F(MeshLevelSetTest, SurfaceEnclosingNothingIsRejected) {
    // The same triangle twice: every edge joins two triangles, but nothing is inside.
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n";
    const std::string what = expectMeshError(write("sheet.obj", text));
    EXPECT_NE(what.find("encloses no volume"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, HugeMeshIsRefusedWithASaneVoxelCount) {
    // 4e21 voxels across: the count was cast to an integer and read -9223372036854775808.
    std::string what = expectMeshError(write("huge.obj", cubeObj(1e20)));
    EXPECT_NE(what.find("spans 4e+21 voxels (of 0.05) along x, from -1e+20 to 1e+20"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find("-9223372036854775808"), std::string::npos) << what;
    // 10000 voxels across, within the extent limit, but its band would hold 3.6e9 voxels.
    what = expectMeshError(write("big.obj", cubeObj(250)));
    EXPECT_NE(what.find("would need about 3.6e+09 voxels (at most 4e+08)"), std::string::npos)
        << what;
}

TEST_F(MeshLevelSetTest, FarReachingSliverIsRefusedBeforeConversion) {
    // A closed sliver 1e9 long and thinner than a voxel: little area, so the band count passes,
    // but the conversion ran for minutes and took 23 GB before it was refused.
    const std::string text =
        "v 0.5 0.5 0.5\nv 1e9 0.5 0.5\nv 0.5 0.500000001 0.5\nv 0.5 0.5 0.500000001\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const std::string what = expectMeshError(write("sliver.obj", text), 0.0625);
    EXPECT_NE(what.find("spans 1.6e+10 voxels (of 0.0625) along x"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 131072"), std::string::npos) << what;
}

TEST_F(MeshLevelSetTest, BadVoxelSizeIsReported) {
    const fs::path file = write("cube.obj", cubeObj(0.5));
    EXPECT_THROW(loadMeshShape(file, 0.0), Error);
    EXPECT_THROW(loadMeshShape(file, -1.0), Error);
    EXPECT_THROW(loadMeshShape(file, 1e-7), Error);  // far too many voxels
}

}  // namespace
}  // namespace modeflow
