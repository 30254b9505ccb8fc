/// A surface scene's mesh is read with the mesh domains' checks and must be a closed, oriented
/// 2-manifold without degenerate triangles; each refusal names the problem and the first
/// offending element.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "engine/core/Error.h"
#include "precompute/geometry/MeshGenerator.h"
#include "precompute/geometry/ObjMesh.h"
#include "precompute/surface/SurfaceTopology.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

#define EXPECT_CONTAINS(haystack, needle)                            \
    EXPECT_NE(std::string(haystack).find(needle), std::string::npos) \
        << "expected \"" << (needle) << "\" in \"" << (haystack) << "\""

/// The message checkClosedSurface refuses `mesh` with, or "".
std::string refusal(const TriangleMesh& mesh) {
    try {
        checkClosedSurface(mesh, "mesh file m.obj");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// A tetrahedron, counter-clockwise seen from outside.
TriangleMesh tetrahedron() {
    return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
            {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

TEST(SurfaceMesh, ClosedMeshesPassWithTheirEdgesAndTopology) {
    const TriangleMesh tet = tetrahedron();
    const SurfaceTopology top = checkClosedSurface(tet, "tet");
    EXPECT_EQ(top.edges.size(), 6u);
    EXPECT_EQ(top.components, 1);
    EXPECT_EQ(top.harmonicCount(4), 0);
    const TriangleMesh torus = makeTorus(12, 8, 1.0, 0.4);
    EXPECT_EQ(checkClosedSurface(torus, "torus").harmonicCount(int(torus.vertices.size())), 2);
    const TriangleMesh twoHoles = makeDoubleTorus(1);
    EXPECT_EQ(
        checkClosedSurface(twoHoles, "double torus").harmonicCount(int(twoHoles.vertices.size())),
        4);
    const TriangleMesh sphere = makeIcosphere(2);
    EXPECT_EQ(checkClosedSurface(sphere, "sphere").harmonicCount(int(sphere.vertices.size())), 0);
}

TEST(SurfaceMesh, RefusesDegenerateTriangles) {
    TriangleMesh mesh = tetrahedron();
    mesh.triangles[1] = {0, 1, 1};
    EXPECT_CONTAINS(refusal(mesh),
                    "mesh file m.obj: triangle 2 (vertices 1, 2, 2) repeats a vertex");
    mesh = tetrahedron();
    mesh.vertices[3] = {0.5, 0.5, 0.0};  // on the line from vertex 2 to vertex 3
    EXPECT_CONTAINS(refusal(mesh), "triangle 4 (vertices 2, 3, 4) has no area");
}

TEST(SurfaceMesh, RefusesOpenSurfaces) {
    TriangleMesh mesh = tetrahedron();
    mesh.triangles.pop_back();
    EXPECT_CONTAINS(refusal(mesh),
                    "the surface is not closed: the edge between vertices 2 and 3 belongs to "
                    "triangle 1 (vertices 1, 3, 2) only");
}

TEST(SurfaceMesh, RefusesEdgesSharedByMoreThanTwoTriangles) {
    TriangleMesh mesh = tetrahedron();
    mesh.vertices.push_back({-1, -1, -1});
    mesh.triangles.push_back({0, 1, 4});
    EXPECT_CONTAINS(refusal(mesh),
                    "not a manifold: the edge between vertices 1 and 2 is shared by 3 triangles "
                    "(1, 2, 5)");
}

TEST(SurfaceMesh, RefusesInconsistentOrientation) {
    TriangleMesh mesh = tetrahedron();
    std::swap(mesh.triangles[3][0], mesh.triangles[3][1]);
    EXPECT_CONTAINS(refusal(mesh),
                    "not consistently oriented: triangle 1 (vertices 1, 3, 2) and triangle 4 "
                    "(vertices 3, 2, 4) both run along the edge between vertices 2 and 3");
}

TEST(SurfaceMesh, RefusesInsideOutSurfaces) {
    TriangleMesh mesh = tetrahedron();
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    EXPECT_CONTAINS(refusal(mesh), "the triangles are clockwise seen from outside");
}

TEST(SurfaceMesh, RefusesVerticesOutsideTrianglesAndPinchedVertices) {
    TriangleMesh mesh = tetrahedron();
    mesh.vertices.push_back({5, 5, 5});
    EXPECT_CONTAINS(refusal(mesh), "vertex 5 belongs to no triangle");
    // Two tetrahedra sharing vertex 1 only: every edge is fine, the vertex is not.
    mesh = tetrahedron();
    const TriangleMesh other = tetrahedron();
    for (std::size_t v = 1; v < 4; ++v)
        mesh.vertices.push_back(
            {-other.vertices[v][0], -other.vertices[v][1], -other.vertices[v][2]});
    for (auto t : other.triangles) {
        for (int& v : t) v = v == 0 ? 0 : v + 3;
        std::swap(t[1], t[2]);  // mirrored: keep it counter-clockwise from outside
        mesh.triangles.push_back(t);
    }
    EXPECT_CONTAINS(refusal(mesh),
                    "vertex 1 is not a manifold point: its triangles form separate fans");
}

TEST(SurfaceMesh, ObjFilesAreReadWithTheMeshDomainsChecks) {
    testing::TestFolder folder;
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(folder / name) << text;
        return folder / name;
    };
    const std::string tet =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    EXPECT_EQ(readObjMesh(write("tet.obj", tet)), tetrahedron());
    try {
        readObjMesh(write("nan.obj", "v 0 0 nan\n" + tet));
        ADD_FAILURE() << "a non-finite coordinate was read";
    } catch (const Error& e) {
        EXPECT_CONTAINS(e.what(), "line 1: vertex 1 coordinate nan is not finite");
    }
    try {
        readObjMesh(write("face.obj", tet + "f 1 2 9\n"));
        ADD_FAILURE() << "a face with a missing vertex was read";
    } catch (const Error& e) {
        EXPECT_CONTAINS(e.what(), "line 9: a face refers to vertex 9, but the file has 4 vertices");
    }
}

}  // namespace
}  // namespace modeflow
