#pragma once
/// @file ObjMesh.h
/// Reads a Wavefront OBJ file into a TriangleMesh: the one OBJ reader of mesh domains and
/// surface scenes. tinyobjloader stays inside ObjMesh.cpp.

#include <filesystem>

#include "engine/core/TriangleMesh.h"

namespace modeflow {

/// The file's vertices (matched by index) and its faces as triangles: polygons are
/// triangulated, and triangles with a repeated vertex are kept (the caller decides what a
/// degenerate triangle means for it).
/// @throw Error naming the file when it is missing, not a regular file or not a readable OBJ,
///        has a vertex coordinate that is not a finite number a float holds or a face that
///        refers to vertices it lacks (both with the line, ObjLineCheck.h), or has no faces.
TriangleMesh readObjMesh(const std::filesystem::path& file);

}  // namespace modeflow
