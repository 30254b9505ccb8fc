#pragma once
/// @file MeshSolids.h
/// Mesh obstacles' and mesh sources' shapes (`shape = "mesh"`): each OBJ file, checked to be a
/// closed, consistently oriented, outward-facing surface, becomes a SolidLevelSet once per run —
/// an obstacle's in the mesh's own frame (the runtime moves and turns the points it samples,
/// never the lattice), a source's in the world.

#include <memory>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/simulation/SolidLevelSet.h"

namespace modeflow {

/// Each obstacle's level sets: one for a rigid mesh, one per file a deforming mesh shows
/// (DeformingSolids.h), none for the other shapes.
using ObstacleShapes = std::vector<std::vector<std::shared_ptr<const SolidLevelSet>>>;

/// The level sets of every mesh obstacle of the scene, in its order: the mesh's depth sampled
/// every half of the grid's finest cell (in world lengths, so every `spacing / scale` mesh
/// units), over the mesh's bounds and two samples beyond. Rigid obstacles with the same file and
/// scale share one.
/// @throw modeflow::Error naming the obstacle and file: unreadable, not a closed, consistently
///        oriented, outward-facing surface (the first offending edge or triangle named),
///        enclosing nothing at that resolution, far larger than the grid, in a 2D scene not
///        crossing the plane z = 0, or a file of a deforming one's sequence the run needs
///        missing.
ObstacleShapes obstacleSolids(const SceneSpec& scene);

/// Hands each obstacle its level sets (obstacleSolids of the same scene, in the same order).
void attachObstacleSolids(std::vector<MovingObstacle>& obstacles, const ObstacleShapes& solids);

/// The level set of every mesh source of the scene (null for the other shapes), in its order:
/// the mesh's depth in world coordinates sampled every half smoke cell, over its bounds and two
/// samples beyond.
/// @throw modeflow::Error naming the source and file, as obstacleSolids.
std::vector<std::shared_ptr<const SolidLevelSet>> sourceSolids(const SceneSpec& scene);

/// Hands each emitter its level set (sourceSolids of the same scene, in the same order).
void attachSourceSolids(std::vector<SmokeEmitter>& emitters,
                        const std::vector<std::shared_ptr<const SolidLevelSet>>& solids);

}  // namespace modeflow
