#pragma once
/// @file TestScenes.h
/// Scenes and shapes built in code, for every test that needs one: grids, the unit disk or ball
/// most tests run on, and each kind of ShapeSpec.

#include <array>

#include "engine/core/SceneSpec.h"

namespace modeflow::testing {

/// A `dim`-dimensional grid of `res` cells over [lo, hi] (2D: res[2] = 1), no domain (the whole
/// box is fluid), 10 velocity and 10 scalar modes.
SceneSpec gridScene(std::array<int, 3> res, Vec3 lo, Vec3 hi, int dim);

/// The unit disk (2D) or ball (3D) at the origin in [−1.1, 1.1]^dim with `cells` per axis and the
/// first `velocityModes` velocity modes.
SceneSpec unitBallScene(int dim, int cells, int velocityModes = 10, int scalarModes = 10);

/// A channel along x over [0, 2] × [0, 1] with `nx` × nx/2 cells around a disk of radius 0.2 at
/// (1, 0.5), its grid periodic as `periodic` says (default: along x): the domain is a box reaching
/// past the grid along x, so the walls are the grid's y bounds.
SceneSpec periodicChannelScene(int nx, std::array<bool, 3> periodic = {true, false, false});

/// A 2D box over [0, 1] × [0, 1.25] of 12 × 15 cells with `open` sides, `modes` velocity modes
/// and no scalar ones.
SceneSpec openBoxScene(std::array<bool, 6> open, int modes);

ShapeSpec ball(const Vec3& centre, double radius, CsgOp op = CsgOp::Union);
ShapeSpec box(const Vec3& min, const Vec3& max, CsgOp op = CsgOp::Union);
ShapeSpec ellipsoid(const Vec3& centre, const Vec3& radii);
ShapeSpec cylinder(const Vec3& centre, double radius, double halfHeight, CsgOp op = CsgOp::Union);
ShapeSpec torus(const Vec3& centre, double major, double minor);

}  // namespace modeflow::testing
