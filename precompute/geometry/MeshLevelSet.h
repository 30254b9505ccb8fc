#pragma once
/// @file MeshLevelSet.h
/// Mesh shapes (`shape = "mesh"`, 3D): a closed OBJ surface turned into a narrow-band signed
/// distance level set. The OpenVDB machinery stays in MeshLevelSet.cpp, the only translation unit
/// that includes its headers (they are slow to compile: tools/README.md, `build.sh`).

#include <filesystem>
#include <memory>

#include "engine/core/TriangleMesh.h"
#include "precompute/geometry/ImplicitShape.h"

namespace modeflow {

/// Reads a Wavefront OBJ file (polygons are triangulated, vertices matched by index) and returns
/// its signed distance, positive inside, sampled trilinearly from a level set of voxel size
/// `voxelSize` (world units, voxel values at integer multiples of it) and a narrow band of
/// `halfWidthVoxels` voxels on each side of the surface. Beyond the band value() is
/// ±halfWidthVoxels·voxelSize, still a lower bound of the distance. Unlike the analytic shapes,
/// the zero set and the 1-Lipschitz bound hold only up to the interpolation error (well under a
/// voxel near the surface). value() is safe to call from many threads at once.
/// @throw Error naming the file when it is missing or not a readable OBJ, has a vertex
///        coordinate that is not a finite number or a face that refers to vertices it lacks (both
///        with the line, ObjLineCheck.h), has no faces, is not a closed, consistently oriented,
///        outward-facing surface (ClosedSurfaceCheck.h), spans more than 131072 voxels on an axis
///        or would need more than 4e8 band voxels, encloses no voxel (flat, doubled, or thinner
///        than a voxel), or the voxel size is not a positive number.
std::unique_ptr<ImplicitShape> loadMeshShape(const std::filesystem::path& objFile, double voxelSize,
                                             double halfWidthVoxels = 3.0);

/// The same for a mesh already read from `objFile` (readObjMesh; the file names it in messages).
std::unique_ptr<ImplicitShape> loadMeshShape(const TriangleMesh& mesh,
                                             const std::filesystem::path& objFile, double voxelSize,
                                             double halfWidthVoxels = 3.0);

}  // namespace modeflow
