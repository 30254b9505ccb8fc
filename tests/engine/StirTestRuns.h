#pragma once
/// @file StirTestRuns.h
/// The scenes `modeflow stir`'s loop tests run (in a window under Xvfb: StirWindowTest; on a
/// NullScreen: StirLoopTest) and what they measure in the results.

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "engine/pipeline/RunInputs.h"
#include "engine/preview/Image.h"
#include "precompute/Precompute.h"

namespace modeflow::testing {

/// A box with a source at the bottom; `dim` 2: 40² cells and the shaped basis "1-10,21-30";
/// 3: 16³ cells and 12 modes.
inline SceneSpec stirScene(int dim) {
    SceneSpec scene;
    scene.name = dim == 2 ? "stir_test_2d" : "stir_test_3d";
    scene.grid.dim = dim;
    const int n = dim == 2 ? 40 : 16;
    scene.grid.resolution = {n, n, dim == 2 ? 1 : n};
    scene.grid.boundsMin = {-1.0, -1.0, dim == 2 ? 0.0 : -1.0};
    scene.grid.boundsMax = {1.0, 1.0, dim == 2 ? 0.0 : 1.0};
    scene.basis.velocityModes =
        dim == 2 ? std::vector<ModeRange>{{1, 10}, {21, 30}} : std::vector<ModeRange>{{1, 12}};
    scene.basis.scalarModes = 0;
    scene.simulation.dt = 0.025;
    scene.output.stepsPerFrame = 1;
    scene.smoke.buoyancy = 0.5;
    SourceSpec source;
    source.shape.kind = ShapeKind::Ball;
    source.shape.center = dim == 2 ? Vec3{0.0, -0.6, 0.0} : Vec3{0.0, 0.0, -0.6};
    source.shape.radius = 0.2;
    source.density = 2.0;
    source.temperature = 1.0;
    scene.sources = {source};
    return scene;
}

/// The scene's run, its initial velocity zero (the basis computed once per executable).
inline const RunInputs& preparedStirRun(int dim) {
    auto prepare = [](int d) {
        const SceneSpec scene = stirScene(d);
        Progress quiet = Progress::silent();
        RunInputs run = prepareRun(scene, computeBasis(scene, quiet));
        run.initialVelocity.setZero();
        return run;
    };
    static const RunInputs two = prepare(2), three = prepare(3);
    return dim == 2 ? two : three;
}

/// The density's centre of mass, in scene coordinates.
inline Vec3 centroid(const MacGrid& grid, const std::vector<double>& density) {
    Vec3 c{};
    double mass = 0.0;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double d = density[std::size_t(grid.cellIndex(x, y, z))];
                mass += d;
                const std::array<int, 3> at{x, y, z};
                for (int a = 0; a < grid.dim; ++a) c[a] += d * grid.cellCentre(a, at[a]);
            }
    for (double& v : c) v /= mass;
    return c;
}

inline Vec3 smokeCentroid(int dim, const std::vector<double>& density) {
    return centroid(MacGrid::fromSpec(preparedStirRun(dim).cache.grid), density);
}

/// The horizontal centre of a picture's bright pixels (the smoke: the background, walls and
/// margins are dark); -1 when there are none.
inline double brightCentreX(const preview::Image& picture) {
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < picture.height; ++y)
        for (int x = 0; x < picture.width; ++x) {
            const preview::Rgba p = picture.pixel(x, y);
            const double brightness = (p[0] + p[1] + p[2]) / 765.0;
            if (brightness > 0.3) {
                sum += brightness * x;
                weight += brightness;
            }
        }
    return weight > 0.0 ? sum / weight : -1.0;
}

/// A left drag along y = 0.75 of the window (through the source) from x0 to x1.
inline std::string drag(double x0, double x1, const std::string& before = "") {
    std::ostringstream s;
    s << before << "0.20 down " << x0 << " 0.75\n";
    for (int i = 1; i <= 6; ++i)
        s << 0.20 + 0.05 * i << " move " << x0 + (x1 - x0) * i / 6.0 << " 0.75\n";
    s << "0.55 up " << x1 << " 0.75\n";
    return s.str();
}

}  // namespace modeflow::testing
