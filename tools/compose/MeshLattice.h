#pragma once
/// @file MeshLattice.h
/// A mesh's depth sampled on a lattice (engine/simulation/SolidLevelSet.h), the steps
/// MeshSolids and DeformingSolids share.

#include <filesystem>
#include <string>
#include <utility>

#include "engine/core/GridSpec.h"
#include "engine/core/TriangleMesh.h"
#include "engine/simulation/SolidLevelSet.h"

namespace modeflow {

/// 2²⁵ floats, 128 MiB: a lattice beyond this is a mesh far larger than the grid.
inline constexpr double kMaxLatticeSamples = 33554432.0;

/// The finest spacing of the grid's axes.
double finestSpacing(const GridSpec& grid);

/// The lowest and highest vertex coordinates along each axis.
std::pair<Vec3, Vec3> meshBounds(const TriangleMesh& mesh);

/// A lattice with no depth yet: every `spacing` mesh units over [lo, hi], two samples beyond.
/// `scale` and `where` for the message.
/// @throw modeflow::Error when it would hold more than kMaxLatticeSamples samples.
SolidLevelSet latticeOver(const Vec3& lo, const Vec3& hi, double spacing, double scale,
                          const std::string& where);

/// Fills `solid.depth` with the mesh's depth, exact to `depth` inside (deeper the band holds a
/// constant), and `solid.radius` with its farthest vertex plus a lattice diagonal.
/// @throw modeflow::Error for a mesh that is not a closed, consistently oriented, outward-facing
///        surface, naming `file`.
void sampleDepth(SolidLevelSet& solid, const TriangleMesh& mesh, const std::filesystem::path& file,
                 double depth);

}  // namespace modeflow
