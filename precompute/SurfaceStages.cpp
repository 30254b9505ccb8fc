/// @file SurfaceStages.cpp

#include "precompute/SurfaceStages.h"

#include <numeric>

#include "engine/core/Error.h"
#include "precompute/geometry/ObjMesh.h"
#include "precompute/surface/SurfaceAdvection.h"
#include "precompute/surface/SurfaceBasis.h"
#include "precompute/surface/SurfaceCoefficients.h"

namespace modeflow {

BasisCache computeSurfaceStages(const SceneSpec& scene, std::string key, Progress& progress) {
    BasisCache cache;
    cache.key = std::move(key);
    cache.kind = BasisKind::Surface;

    progress.begin("surface mesh and operators");
    const std::string where = "[surface].mesh: mesh file " + scene.surface->meshFile.string();
    TriangleMesh mesh;
    SurfaceTopology topology;
    try {
        mesh = readObjMesh(scene.surface->meshFile);
        topology = checkClosedSurface(mesh, where);
    } catch (const Error& e) {
        const std::string message = e.what();
        throw Error(message.rfind("[surface]", 0) == 0 ? message : "[surface].mesh: " + message);
    }
    const SurfaceDec dec = buildSurfaceDec(mesh, topology);
    cache.faces.resize(topology.edges.size());
    std::iota(cache.faces.begin(), cache.faces.end(), 0);
    cache.faceStar = dec.star1;
    cache.cells.resize(mesh.triangles.size());
    std::iota(cache.cells.begin(), cache.cells.end(), 0);
    cache.cellStar = dec.star2;
    cache.scalar.cells.resize(mesh.vertices.size());
    std::iota(cache.scalar.cells.begin(), cache.scalar.cells.end(), 0);
    cache.scalar.cellStar = dec.star0;
    cache.surface.edges = topology.edges;
    cache.timings.emplace_back("operators", progress.end());

    progress.begin("surface eigensolve");
    const auto counter = [&progress](long ops) {
        progress.update(std::to_string(ops) + " solves");
    };
    const SurfaceBasisResult basis =
        solveSurfaceBasis(dec, scene.basis.velocityModes, scene.basis.scalarModes, counter);
    cache.velocity.eigenvalues = basis.velocityEigenvalues;
    cache.velocity.modes = basis.velocityModes;
    cache.velocity.modeNumbers = basis.modeNumbers;
    cache.velocity.harmonic = basis.harmonicCount;
    cache.scalar.eigenvalues = basis.scalarEigenvalues;
    cache.scalar.modes = basis.scalarModes;
    cache.scalar.omittedConstants = basis.omittedConstants;
    cache.timings.emplace_back("eigensolve", progress.end());

    progress.begin("structural coefficients");
    cache.coefficients.packed = assembleSurfaceCoefficients(dec, mesh, cache.velocity.modes);
    cache.surface.advection = surfaceAdvection(dec, mesh, cache.scalar.modes, cache.velocity.modes);
    cache.surface.vertexVelocity = surfaceVertexVelocity(dec, mesh, cache.velocity.modes);
    cache.timings.emplace_back("coefficients", progress.end());
    cache.surface.mesh = std::move(mesh);
    return cache;
}

}  // namespace modeflow
