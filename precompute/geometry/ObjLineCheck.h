#pragma once
/// @file ObjLineCheck.h
/// tinyobjloader reads a vertex coordinate it cannot parse (`nan`, `abc`, a missing one) as 0 and
/// does not look at face indices, so a broken OBJ file becomes a mesh with a corner at the
/// origin. These lines are checked first, each problem named with its line.

#include <filesystem>

namespace modeflow {

/// Checks every `v` line (three coordinates, each a finite number a float holds) and every `f`
/// line (each vertex index refers to a vertex of the file; texture and normal indices are left
/// to tinyobjloader) of an OBJ file, counting lines as tinyobjloader does.
/// @throw Error "mesh file <file>, line <n>: vertex 7 coordinate \"abc\" is not a number", or
///        naming the face's missing vertex; or when the file cannot be read.
void checkObjLines(const std::filesystem::path& file);

}  // namespace modeflow
