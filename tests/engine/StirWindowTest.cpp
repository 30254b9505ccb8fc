/// `modeflow stir`'s window, run for real: under Xvfb on lavapipe (tests/CMakeLists.txt wraps
/// files named *WindowTest in xvfb-run) with the validation layer on, driven by input scripts
/// on the frame clock, so every run is reproducible.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "engine/dynamics/CachedCoefficients.h"
#include "engine/pipeline/RunInputs.h"
#include "engine/stir/StirApp.h"
#include "engine/stir/StirView.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/FluidMask.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

/// A box with a source at the bottom; `dim` 2: 40² cells and the shaped basis "1-10,21-30";
/// 3: 16³ cells and 12 modes.
SceneSpec stirScene(int dim) {
    SceneSpec scene;
    scene.name = dim == 2 ? "stir_test_2d" : "stir_test_3d";
    scene.grid.dim = dim;
    const int n = dim == 2 ? 40 : 16;
    scene.grid.resolution = {n, n, dim == 2 ? 1 : n};
    scene.grid.boundsMin = {-1.0, -1.0, dim == 2 ? 0.0 : -1.0};
    scene.grid.boundsMax = {1.0, 1.0, dim == 2 ? 0.0 : 1.0};
    scene.basis.velocityModes = dim == 2 ? std::vector<ModeRange>{{1, 10}, {21, 30}}
                                         : std::vector<ModeRange>{{1, 12}};
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
const RunInputs& prepared(int dim) {
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

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "modeflow-stir-window-test";
    fs::create_directories(dir);
    return dir / name;
}

/// A scripted run in a 640 × 480 window (`sized` false: the default size).
stir::StirReport run(int dim, const std::string& script, int frames = 40,
                     const fs::path& screenshot = {}, bool sized = true) {
    stir::StirOptions options;
    if (sized) {
        options.width = 640;
        options.height = 480;
    }
    options.frames = frames;
    options.screenshot = screenshot;
    options.screenshotFolder = scratch("");
    options.statistics = false;
    options.backend.vulkan.validation = true;
    options.script = stir::parseInputScript(script, "test script");
    std::ostringstream log;
    return stir::runStir(options, prepared(dim), log);
}

/// The density's centre of mass, in scene coordinates.
Vec3 centroid(const MacGrid& grid, const std::vector<double>& density) {
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

Vec3 smokeCentroid(int dim, const stir::StirReport& report) {
    return centroid(MacGrid::fromSpec(prepared(dim).cache.grid), report.smoke.density);
}

/// The horizontal centre of the bright pixels of a PNG (the smoke: the background, walls and
/// margins are dark).
double brightCentreX(const fs::path& png, int& width, int& height) {
    int channels = 0;
    unsigned char* pixels = stbi_load(png.string().c_str(), &width, &height, &channels, 3);
    if (!pixels) return -1.0;
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = pixels + 3 * (std::size_t(y) * width + x);
            const double brightness = (p[0] + p[1] + p[2]) / 765.0;
            if (brightness > 0.3) {
                sum += brightness * x;
                weight += brightness;
            }
        }
    stbi_image_free(pixels);
    return weight > 0.0 ? sum / weight : -1.0;
}

/// A left drag along y = 0.75 of the window (through the source) from x0 to x1.
std::string drag(double x0, double x1, const std::string& before = "") {
    std::ostringstream s;
    s << before << "0.20 down " << x0 << " 0.75\n";
    for (int i = 1; i <= 6; ++i) s << 0.20 + 0.05 * i << " move " << x0 + (x1 - x0) * i / 6.0 << " 0.75\n";
    s << "0.55 up " << x1 << " 0.75\n";
    return s.str();
}

TEST(StirWindowTest, DragCarriesTheSmokeAlongAndThePictureShowsIt) {
    const fs::path still = scratch("still.png"), right = scratch("right.png");
    const stir::StirReport none = run(2, "", 40, still);
    const stir::StirReport toRight = run(2, drag(0.3, 0.7), 40, right);
    const stir::StirReport toLeft = run(2, drag(0.7, 0.3), 40);
    EXPECT_EQ(none.validationMessages, 0u);
    const double x0 = smokeCentroid(2, none)[0];
    EXPECT_NEAR(x0, 0.0, 0.02) << "without a drag the plume rises straight";
    EXPECT_GT(smokeCentroid(2, toRight)[0], x0 + 0.1);
    EXPECT_LT(smokeCentroid(2, toLeft)[0], x0 - 0.1);
    // The screenshots show the same: the bright smoke moved right.
    int w0 = 0, h0 = 0, w1 = 0, h1 = 0;
    const double still0 = brightCentreX(still, w0, h0), moved = brightCentreX(right, w1, h1);
    EXPECT_EQ(w0, 640);
    EXPECT_EQ(h0, 480);
    ASSERT_GT(still0, 0.0) << "no smoke in the still screenshot";
    EXPECT_NEAR(still0, 320.0, 10.0);
    EXPECT_GT(moved, still0 + 20.0);
}

TEST(StirWindowTest, PaddleFollowsTheDragAndPushesTheSmoke) {
    const stir::StirReport none = run(2, "0.0 key m\n", 40);
    const stir::StirReport pushed = run(2, drag(0.3, 0.7, "0.0 key m\n"), 40);
    EXPECT_NE(pushed.status.find("mouse: paddle"), std::string::npos) << pushed.status;
    EXPECT_GT(smokeCentroid(2, pushed)[0], smokeCentroid(2, none)[0] + 0.05);
}

TEST(StirWindowTest, WindowResizesWithoutErrors) {
    const fs::path shot = scratch("resized.png");
    const stir::StirReport report =
        run(2, "0.1 resize 800 400\n0.3 resize 320 240\n", 20, shot);
    EXPECT_EQ(report.width, 320);
    EXPECT_EQ(report.height, 240);
    EXPECT_EQ(report.frames, 20);
    int w = 0, h = 0;
    brightCentreX(shot, w, h);
    EXPECT_EQ(w, 320);
    EXPECT_EQ(h, 240);
}

TEST(StirWindowTest, DefaultWindowFitsTheDevice) {
    const stir::StirReport report = run(2, "", 5, {}, false);
    const bool cpu = vulkan::VulkanContext().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    EXPECT_EQ(report.width, cpu ? 960 : 1280);
    EXPECT_EQ(report.height, cpu ? 540 : 720);
}

TEST(StirWindowTest, KeysPauseSwitchAndReset) {
    // Paused from the start: no time passes, no smoke appears; one step key advances one frame.
    const stir::StirReport paused = run(2, "0.0 key space\n0.1 key s\n", 10);
    EXPECT_NEAR(paused.simulatedTime, 0.025, 1e-12);

    const stir::StirReport switched =
        run(2, "0.05 key i\n0.1 key ]\n0.15 key b\n0.2 key p\n0.25 key v\n0.7 key r\n", 30);
    EXPECT_NE(switched.status.find("explicit"), std::string::npos) << switched.status;
    EXPECT_EQ(switched.status.find("viscosity 0 "), std::string::npos) << switched.status;
    EXPECT_EQ(switched.modes, 10) << "b switches from 1-10,21-30 to the leading range";
    EXPECT_NE(switched.status.find("(1-10)"), std::string::npos) << switched.status;
    EXPECT_TRUE(fs::exists(scratch("stir_test_2d_stir_0001.png")));
    // Reset at 0.7 s: the clock restarted and the smoke is only what 0.05 s of emission made.
    EXPECT_LT(switched.simulatedTime, 0.1);

    const stir::StirReport back = run(2, "0.1 key b\n0.2 key b\n", 10);
    EXPECT_EQ(back.modes, 20) << "b cycles back to the whole basis";
}

TEST(StirWindowTest, ThreeDimensionalSceneOrbitsZoomsAndStirsAcrossTheView) {
    const std::string orbit = "0.05 rdown 0.5 0.5\n0.1 move 0.6 0.45\n0.15 rup 0.6 0.45\n0.15 scroll 2\n";
    const stir::StirReport none = run(3, orbit, 40);
    const std::string stroke = orbit + "0.2 down 0.3 0.7\n0.3 move 0.5 0.7\n0.4 move 0.7 0.7\n0.45 up 0.7 0.7\n";
    const stir::StirReport stirred = run(3, stroke, 40);
    EXPECT_EQ(stirred.validationMessages, 0u);
    // The smoke moves along the drag's direction in the scene: the stroke's two ends on the
    // plane through the box's centre, seen by the orbited and zoomed camera.
    stir::StirView view(MacGrid::fromSpec(prepared(3).cache.grid));
    view.orbit(0.1, -0.05);
    view.zoom(2);
    const auto from = view.scenePoint(0.3, 0.7, 640, 480), to = view.scenePoint(0.7, 0.7, 640, 480);
    ASSERT_TRUE(from && to);
    const Vec3 c0 = smokeCentroid(3, none), c1 = smokeCentroid(3, stirred);
    double along = 0.0, length = 0.0;
    for (int a = 0; a < 3; ++a) {
        along += (c1[a] - c0[a]) * ((*to)[a] - (*from)[a]);
        length += ((*to)[a] - (*from)[a]) * ((*to)[a] - (*from)[a]);
    }
    EXPECT_GT(along / std::sqrt(length), 0.05)
        << "smoke displacement along the stroke; centroid moved by " << c1[0] - c0[0] << ", "
        << c1[1] - c0[1] << ", " << c1[2] - c0[2];
}

}  // namespace
}  // namespace modeflow
