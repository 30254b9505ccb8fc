#include "tests/support/TestScenes.h"

namespace modeflow::testing {

SceneSpec gridScene(std::array<int, 3> res, Vec3 lo, Vec3 hi, int dim) {
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

SceneSpec unitBallScene(int dim, int cells, int velocityModes, int scalarModes) {
    const double z = dim == 3 ? 1.1 : 0.0;
    SceneSpec s = gridScene({cells, cells, cells}, {-1.1, -1.1, -z}, {1.1, 1.1, z}, dim);
    s.domain = {ball({0.0, 0.0, 0.0}, 1.0)};
    s.basis.velocityModes = {{1, velocityModes}};
    s.basis.scalarModes = scalarModes;
    return s;
}

SceneSpec periodicChannelScene(int nx, std::array<bool, 3> periodic) {
    SceneSpec s = gridScene({nx, nx / 2, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2);
    s.grid.periodic = periodic;
    s.domain = {box({-1.0, -1.0, 0.0}, {3.0, 2.0, 0.0}),
                ball({1.0, 0.5, 0.0}, 0.2, CsgOp::Subtract)};
    return s;
}

SceneSpec openBoxScene(std::array<bool, 6> open, int modes) {
    SceneSpec scene = gridScene({12, 15, 1}, {0.0, 0.0, 0.0}, {1.0, 1.25, 0.0}, 2);
    scene.grid.open = open;
    scene.basis.velocityModes = {{1, modes}};
    scene.basis.scalarModes = 0;
    return scene;
}

ShapeSpec ball(const Vec3& centre, double radius, CsgOp op) {
    ShapeSpec s;
    s.kind = ShapeKind::Ball;
    s.center = centre;
    s.radius = radius;
    s.op = op;
    return s;
}

ShapeSpec box(const Vec3& min, const Vec3& max, CsgOp op) {
    ShapeSpec s;
    s.kind = ShapeKind::Box;
    s.min = min;
    s.max = max;
    s.op = op;
    return s;
}

ShapeSpec ellipsoid(const Vec3& centre, const Vec3& radii) {
    ShapeSpec s;
    s.kind = ShapeKind::Ellipsoid;
    s.center = centre;
    s.radii = radii;
    return s;
}

ShapeSpec cylinder(const Vec3& centre, double radius, double halfHeight, CsgOp op) {
    ShapeSpec s;
    s.op = op;
    s.kind = ShapeKind::Cylinder;
    s.center = centre;
    s.radius = radius;
    s.halfHeight = halfHeight;
    return s;
}

ShapeSpec torus(const Vec3& centre, double major, double minor) {
    ShapeSpec s;
    s.kind = ShapeKind::Torus;
    s.center = centre;
    s.majorRadius = major;
    s.minorRadius = minor;
    return s;
}

}  // namespace modeflow::testing
