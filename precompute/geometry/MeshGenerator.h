#pragma once
/// @file MeshGenerator.h
/// Closed triangle meshes made in code: icospheres and the irregular "blob" that mesh-domain scenes
/// use (scenes/meshes/blob.obj = writeBlobMeshObj(path, 4, 1)). No OpenVDB here.

#include <array>
#include <filesystem>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "engine/core/TriangleMesh.h"

namespace modeflow {

/// The icosahedron, each face split in four `subdivisions` times, vertices pushed onto the sphere
/// of `radius` around `center`. 10·4^s + 2 vertices, 20·4^s triangles; closed and manifold.
TriangleMesh makeIcosphere(int subdivisions, double radius = 1.0, const Vec3& center = {});

/// A closed, star-shaped (around the origin) irregular blob of radius about 0.8 (within
/// [0.62, 0.98]): an icosphere whose radius is modulated by a few random low-frequency
/// sinusoids. Deterministic for a given seed on every platform (no std distributions).
TriangleMesh makeBlobMesh(int subdivisions, unsigned seed);

/// Writes `v x y z` and 1-based `f a b c` lines.
/// @throw Error when the file cannot be written.
void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh);

/// writeObj(file, makeBlobMesh(subdivisions, seed)).
void writeBlobMeshObj(const std::filesystem::path& file, int subdivisions, unsigned seed);

}  // namespace modeflow
