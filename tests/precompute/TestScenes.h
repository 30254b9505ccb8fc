#pragma once
// Scenes built in code for the precompute tests.

#include <gtest/gtest.h>

#include "precompute/BasisChecks.h"
#include "engine/core/SceneSpec.h"

namespace modeflow::test {

inline SceneSpec gridScene(std::array<int, 3> res, Vec3 lo, Vec3 hi, int dim) {
    SceneSpec s;
    s.name = "test";
    s.grid.dim = dim;
    s.grid.resolution = res;
    if (dim == 2) s.grid.resolution[2] = 1;
    s.grid.boundsMin = lo;
    s.grid.boundsMax = hi;
    s.basis.velocityModes = {{1, 10}};
    s.basis.scalarModes = 10;
    return s;
}

inline ShapeSpec ball(Vec3 centre, double radius, CsgOp op = CsgOp::Union) {
    ShapeSpec b;
    b.kind = ShapeKind::Ball;
    b.center = centre;
    b.radius = radius;
    b.op = op;
    return b;
}

inline ShapeSpec box(Vec3 lo, Vec3 hi) {
    ShapeSpec b;
    b.kind = ShapeKind::Box;
    b.min = lo;
    b.max = hi;
    return b;
}

/// The contract every velocity basis meets (DESIGN §2): max |dΨ|/|Ψ| and |ΨᵀMΨ − I| ≤ 1e-10,
/// recomputed from the stored data.
inline void expectValidVelocityBasis(const BasisCache& cache) {
    const BasisChecks checks = checkBasis(cache);
    EXPECT_LE(checks.maxDivergence, 1e-10);
    EXPECT_LE(checks.velocityOrthonormality, 1e-10);
}

}  // namespace modeflow::test
