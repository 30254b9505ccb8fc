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

/// A ring torus around the z axis through `center`: `around` (even) × `across` vertices on the
/// circles of the major and the minor radius, each ring turned half a step from the last.
/// Genus 1: two harmonic 1-forms.
TriangleMesh makeTorus(int around, int across, double majorRadius, double minorRadius,
                       const Vec3& center = {});

/// The closed surface of a union of unit cubes (integer corners `voxels`, face-connected, no
/// two touching along an edge or a corner only), each cube face split into `subdivisions`²
/// squares of two right triangles, scaled by `scale` and centred on the origin. A 5×3×1 slab
/// with two cubes removed (makeDoubleTorus) has genus 2.
TriangleMesh makeVoxelSurface(const std::vector<std::array<int, 3>>& voxels, int subdivisions,
                              double scale);

/// makeVoxelSurface of a 5×3×1 slab of cubes with two holes through it: genus 2, four harmonic
/// 1-forms, 2.5 × 1.5 × 0.5 scene units.
TriangleMesh makeDoubleTorus(int subdivisions);

/// Writes `v x y z` and 1-based `f a b c` lines.
/// @throw Error when the file cannot be written.
void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh);

/// writeObj(file, makeBlobMesh(subdivisions, seed)).
void writeBlobMeshObj(const std::filesystem::path& file, int subdivisions, unsigned seed);

}  // namespace modeflow
