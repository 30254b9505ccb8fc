#include "tests/support/StirRuns.h"

#include <sstream>

#include "engine/core/MacGrid.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/TestScenes.h"

namespace modeflow::testing {

SceneSpec stirScene(int dim) {
    const int n = dim == 2 ? 40 : 16;
    SceneSpec scene = gridScene({n, n, n}, {-1.0, -1.0, dim == 2 ? 0.0 : -1.0},
                                {1.0, 1.0, dim == 2 ? 0.0 : 1.0}, dim);
    scene.name = dim == 2 ? "stir_test_2d" : "stir_test_3d";
    scene.basis.velocityModes =
        dim == 2 ? std::vector<ModeRange>{{1, 10}, {21, 30}} : std::vector<ModeRange>{{1, 12}};
    scene.basis.scalarModes = 0;
    scene.simulation.dt = 0.025;
    scene.output.stepsPerFrame = 1;
    scene.smoke.buoyancy = 0.5;
    SourceSpec source;
    source.shape = ball(dim == 2 ? Vec3{0.0, -0.6, 0.0} : Vec3{0.0, 0.0, -0.6}, 0.2);
    source.density = 2.0;
    source.temperature = 1.0;
    scene.sources = {source};
    return scene;
}

const RunInputs& preparedStirRun(int dim) {
    auto prepare = [](int d) {
        RunInputs run = sharedRun(stirScene(d));
        run.initialVelocity.setZero();
        return run;
    };
    if (dim == 2) {
        static const RunInputs two = prepare(2);
        return two;
    }
    static const RunInputs three = prepare(3);
    return three;
}

Vec3 smokeCentroid(int dim, const std::vector<double>& density) {
    return centroid(MacGrid::fromSpec(preparedStirRun(dim).cache.grid), density);
}

double brightCentreX(const preview::Image& picture) {
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

std::string drag(double x0, double x1, const std::string& before) {
    std::ostringstream s;
    s << before << "0.20 down " << x0 << " 0.75\n";
    for (int i = 1; i <= 6; ++i)
        s << 0.20 + 0.05 * i << " move " << x0 + (x1 - x0) * i / 6.0 << " 0.75\n";
    s << "0.55 up " << x1 << " 0.75\n";
    return s.str();
}

}  // namespace modeflow::testing
