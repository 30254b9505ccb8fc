/// @file SceneLoaderTest.cpp
/// Scene files → SceneSpec: every field round trips, defaults fill the gaps, and each kind of
/// mistake is refused with a message naming the file and the key.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "precompute/scene/SceneLoader.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

/// A private temporary folder, removed with the fixture.
class SceneLoaderTest : public ::testing::Test {
protected:
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = mDir / name;
        fs::create_directories(path.parent_path());
        std::ofstream(path) << text;
        return path;
    }

    testing::TestFolder mFolder;
    const fs::path mDir = mFolder.path();
};

constexpr const char* kGrid2d = R"(
[grid]
resolution = [64, 64]
bounds_min = [-1.1, -1.1]
bounds_max = [1.1, 1.1]
)";

constexpr const char* kGrid3d = R"(
[grid]
resolution = [16, 16, 16]
bounds_min = [-1, -1, -1]
bounds_max = [1, 1, 1]
)";

constexpr const char* kBasis = R"(
[basis]
velocity_modes = 10
)";

/// The message of the Error that parsing `text` throws, or "" if it parses.
std::string errorOf(const std::string& text, const fs::path& origin = "scenes/bad.toml") {
    try {
        parseScene(text, origin);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// The shortest text that reads back as `x`, for numbers put in scene text.
std::string formatNumberForTest(double x) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, end);
}

/// The message of parseModeRanges' Error for `text`, or "".
std::string parseModeRangesError(const std::string& text) {
    try {
        parseModeRanges(text, "--modes");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

#define EXPECT_CONTAINS(haystack, needle)                            \
    EXPECT_NE(std::string(haystack).find(needle), std::string::npos) \
        << "expected \"" << (needle) << "\" in \"" << (haystack) << "\""

TEST_F(SceneLoaderTest, FullSceneRoundTripsEveryField) {
    write("meshes/bunny.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const fs::path file = write("full_scene.toml", R"(
[grid]
resolution = [48, 32, 24]
bounds_min = [-1.5, -1, -0.5]
bounds_max = [1.5, 1.0, 0.5]

[[domain]]
shape = "box"
min = [-1.4, -0.9, -0.4]
max = [1.4, 0.9, 0.4]

[[domain]]
shape = "ball"
center = [0.5, 0.0, 0.0]
radius = 0.25
op = "subtract"

[[domain]]
shape = "ellipsoid"
center = [0, 0, 0]
radii = [1.2, 0.8, 0.35]
op = "intersect"

[[domain]]
shape = "cylinder"
center = [-0.5, 0.0, 0.0]
radius = 0.2
half_height = 0.3
op = "subtract"

[[domain]]
shape = "torus"
center = [0.0, 0.0, 0.1]
major_radius = 0.6
minor_radius = 0.1
op = "union"

[[domain]]
shape = "mesh"
file = "meshes/bunny.obj"
op = "subtract"

[basis]
modes = "1-10, 21-25,30"
scalar_modes = 7
scalar_boundary = "dirichlet"
wall = "no-slip"
boundary = "staircase"
subsamples = 8
coefficients = "tensor-free"
eigensolver = "slepc"

[simulation]
dt = 0.005
integrator = "rk4"
viscosity = 0.01
alpha = 0.05

[initial]
velocity = "vortices"
energy = 2.5

[[initial.vortex]]
center = [0.1, 0.0, -0.2]
normal = [0, 0, 2]
ring_radius = 0.3
radius = 0.05
strength = -1.5

[[source]]
shape = "ball"
center = [0.0, 0.0, -0.3]
radius = 0.1
density = 0.5
temperature = 2.0
start = 0.5
end = 1.5

[[source]]
shape = "box"
min = [-0.1, -0.1, -0.4]
max = [0.1, 0.1, -0.35]
density = 3
temperature = -1

[smoke]
buoyancy = -0.75
resolution_scale = 3
advection = "semi-lagrangian"

[output]
frames = 10
steps_per_frame = 5
)");
    const SceneSpec scene = loadScene(file);

    EXPECT_EQ(scene.sourceFile, file);
    EXPECT_EQ(scene.name, "full_scene");

    EXPECT_EQ(scene.grid.dim, 3);
    EXPECT_EQ(scene.grid.resolution, (std::array<int, 3>{48, 32, 24}));
    EXPECT_EQ(scene.grid.boundsMin, (Vec3{-1.5, -1.0, -0.5}));
    EXPECT_EQ(scene.grid.boundsMax, (Vec3{1.5, 1.0, 0.5}));

    ASSERT_EQ(scene.domain.size(), 6u);
    ShapeSpec box;
    box.kind = ShapeKind::Box;
    box.min = {-1.4, -0.9, -0.4};
    box.max = {1.4, 0.9, 0.4};
    EXPECT_EQ(scene.domain[0], box);

    ShapeSpec ball;
    ball.kind = ShapeKind::Ball;
    ball.center = {0.5, 0.0, 0.0};
    ball.radius = 0.25;
    ball.op = CsgOp::Subtract;
    EXPECT_EQ(scene.domain[1], ball);

    ShapeSpec ellipsoid;
    ellipsoid.kind = ShapeKind::Ellipsoid;
    ellipsoid.radii = {1.2, 0.8, 0.35};
    ellipsoid.op = CsgOp::Intersect;
    EXPECT_EQ(scene.domain[2], ellipsoid);

    ShapeSpec cylinder;
    cylinder.kind = ShapeKind::Cylinder;
    cylinder.center = {-0.5, 0.0, 0.0};
    cylinder.radius = 0.2;
    cylinder.halfHeight = 0.3;
    cylinder.op = CsgOp::Subtract;
    EXPECT_EQ(scene.domain[3], cylinder);

    ShapeSpec torus;
    torus.kind = ShapeKind::Torus;
    torus.center = {0.0, 0.0, 0.1};
    torus.majorRadius = 0.6;
    torus.minorRadius = 0.1;
    EXPECT_EQ(scene.domain[4], torus);

    EXPECT_EQ(scene.domain[5].kind, ShapeKind::Mesh);
    EXPECT_EQ(scene.domain[5].op, CsgOp::Subtract);
    EXPECT_TRUE(scene.domain[5].meshFile.is_absolute() == file.is_absolute());
    EXPECT_TRUE(fs::equivalent(scene.domain[5].meshFile, mDir / "meshes" / "bunny.obj"));

    EXPECT_EQ(scene.basis.velocityModes, (std::vector<ModeRange>{{1, 10}, {21, 25}, {30, 30}}));
    EXPECT_EQ(scene.basis.velocityCount(), 16);
    EXPECT_EQ(scene.basis.highestVelocityMode(), 30);
    EXPECT_EQ(scene.basis.scalarModes, 7);
    EXPECT_EQ(scene.basis.scalarBoundary, ScalarBoundary::Dirichlet);
    EXPECT_EQ(scene.basis.wall, WallKind::NoSlip);
    EXPECT_EQ(scene.basis.boundary, BoundaryTreatment::Staircase);
    EXPECT_EQ(scene.basis.subsamples, 8);
    EXPECT_EQ(scene.basis.coefficients, CoefficientStorage::TensorFree);
    EXPECT_EQ(scene.basis.eigensolver, EigensolverChoice::Slepc);

    EXPECT_EQ(scene.simulation.dt, 0.005);
    EXPECT_EQ(scene.simulation.integrator, Integrator::Rk4);
    EXPECT_EQ(scene.simulation.viscosity, 0.01);
    EXPECT_EQ(scene.simulation.alpha, 0.05);

    EXPECT_EQ(scene.initial.velocity, InitialVelocity::Vortices);
    EXPECT_EQ(scene.initial.energy, 2.5);
    ASSERT_EQ(scene.initial.vortices.size(), 1u);
    const VortexSpec& ring = scene.initial.vortices[0];
    EXPECT_EQ(ring.center, (Vec3{0.1, 0.0, -0.2}));
    EXPECT_EQ(ring.normal, (Vec3{0.0, 0.0, 2.0}));
    EXPECT_EQ(ring.ringRadius, 0.3);
    EXPECT_EQ(ring.radius, 0.05);
    EXPECT_EQ(ring.strength, -1.5);

    ASSERT_EQ(scene.sources.size(), 2u);
    EXPECT_EQ(scene.sources[0].shape.kind, ShapeKind::Ball);
    EXPECT_EQ(scene.sources[0].shape.center, (Vec3{0.0, 0.0, -0.3}));
    EXPECT_EQ(scene.sources[0].shape.radius, 0.1);
    EXPECT_EQ(scene.sources[0].density, 0.5);
    EXPECT_EQ(scene.sources[0].temperature, 2.0);
    EXPECT_EQ(scene.sources[0].start, 0.5);
    EXPECT_EQ(scene.sources[0].end, 1.5);
    EXPECT_EQ(scene.sources[1].start, 0.0);
    EXPECT_EQ(scene.sources[1].end, std::numeric_limits<double>::infinity());
    EXPECT_EQ(scene.sources[1].shape.kind, ShapeKind::Box);
    EXPECT_EQ(scene.sources[1].shape.min, (Vec3{-0.1, -0.1, -0.4}));
    EXPECT_EQ(scene.sources[1].shape.max, (Vec3{0.1, 0.1, -0.35}));
    EXPECT_EQ(scene.sources[1].density, 3.0);
    EXPECT_EQ(scene.sources[1].temperature, -1.0);

    EXPECT_EQ(scene.smoke.buoyancy, -0.75);
    EXPECT_EQ(scene.smoke.resolutionScale, 3);
    EXPECT_EQ(scene.smoke.advection, AdvectionScheme::SemiLagrangian);
    EXPECT_EQ(scene.output.frames, 10);
    EXPECT_EQ(scene.output.stepsPerFrame, 5);
}

TEST_F(SceneLoaderTest, ObstaclesFollowKeyFramedPaths) {
    const SceneSpec scene = parseScene(std::string(kGrid2d) + kBasis + R"(
[[obstacle]]
shape = "capsule"
radius = 0.1
axis = [0.0, 0.3]
path = [[0.0, -0.5, 0.0], [1.0, 0.5, 0.0], [2.0, 0.5, 0.5]]
[[obstacle]]
shape = "box"
half_size = [0.1, 0.2]
path = [[0.0, 0.0, -0.5]]
)",
                                       "obstacles.toml");
    ASSERT_EQ(scene.obstacles.size(), 2u);
    EXPECT_EQ(scene.obstacles[0].shape, ObstacleShape::Capsule);
    EXPECT_EQ(scene.obstacles[0].axis, (Vec3{0.0, 0.3, 0.0}));
    ASSERT_EQ(scene.obstacles[0].path.size(), 3u);
    EXPECT_EQ(scene.obstacles[0].path[2].first, 2.0);
    EXPECT_EQ(scene.obstacles[0].path[2].second, (Vec3{0.5, 0.5, 0.0}));
    EXPECT_EQ(scene.obstacles[1].halfSize, (Vec3{0.1, 0.2, 0.0}));

    const std::string base = std::string(kGrid2d) + kBasis + "[[obstacle]]\nshape = \"ball\"\n";
    EXPECT_CONTAINS(errorOf(base + "radius = 0.1\npath = [[1.0, 0.0, 0.0], [0.5, 0.1, 0.0]]\n"),
                    "key frame times must increase");
    EXPECT_CONTAINS(errorOf(base + "radius = 0.1\npath = [[1.0, 0.0]]\n"), "[t, position]");
    EXPECT_CONTAINS(errorOf(base + "path = [[0.0, 0.0, 0.0]]\n"), "radius");
    EXPECT_CONTAINS(
        errorOf(base + "radius = 0.1\nhalf_size = [0.1, 0.1]\npath = [[0.0, 0.0, 0.0]]\n"),
        "half_size: not used by a ball");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + kBasis + "[[obstacle]]\nshape = \"cone\"\n"),
                    "cone");
}

TEST_F(SceneLoaderTest, MinimalSceneGetsDefaults) {
    const SceneSpec scene = parseScene(std::string(kGrid2d) + kBasis, "somewhere/minimal.toml");
    EXPECT_EQ(scene.name, "minimal");
    EXPECT_EQ(scene.sourceFile, fs::path("somewhere/minimal.toml"));

    EXPECT_EQ(scene.grid.dim, 2);
    EXPECT_EQ(scene.grid.resolution, (std::array<int, 3>{64, 64, 1}));
    EXPECT_EQ(scene.grid.boundsMin, (Vec3{-1.1, -1.1, 0.0}));
    EXPECT_EQ(scene.grid.boundsMax, (Vec3{1.1, 1.1, 1.0}));
    EXPECT_TRUE(scene.domain.empty());

    const BasisSpec basisDefaults;
    EXPECT_EQ(scene.basis.velocityModes, (std::vector<ModeRange>{{1, 10}}));
    EXPECT_EQ(scene.basis.scalarModes, basisDefaults.scalarModes);
    EXPECT_EQ(scene.basis.scalarBoundary, ScalarBoundary::Neumann);
    EXPECT_EQ(scene.basis.wall, WallKind::FreeSlip);
    EXPECT_EQ(scene.basis.boundary, BoundaryTreatment::CutCell);
    EXPECT_EQ(scene.basis.subsamples, 4);
    EXPECT_EQ(scene.basis.coefficients, CoefficientStorage::Auto);
    EXPECT_EQ(scene.basis.eigensolver, EigensolverChoice::Automatic);

    const SimulationSpec sim;
    EXPECT_EQ(scene.simulation.dt, sim.dt);
    EXPECT_EQ(scene.simulation.integrator, sim.integrator);
    EXPECT_EQ(scene.simulation.viscosity, sim.viscosity);
    EXPECT_EQ(scene.simulation.alpha, sim.alpha);
    const InitialSpec initial;
    EXPECT_EQ(scene.initial.velocity, initial.velocity);
    EXPECT_EQ(scene.initial.energy, initial.energy);
    EXPECT_EQ(scene.initial.seed, initial.seed);
    EXPECT_TRUE(scene.sources.empty());
    EXPECT_EQ(scene.smoke.buoyancy, SmokeSpec{}.buoyancy);
    EXPECT_EQ(scene.smoke.resolutionScale, SmokeSpec{}.resolutionScale);
    EXPECT_EQ(scene.output.frames, OutputSpec{}.frames);
    EXPECT_EQ(scene.output.stepsPerFrame, OutputSpec{}.stepsPerFrame);
}

TEST_F(SceneLoaderTest, SourceDefaultsAndPartialTables) {
    const SceneSpec scene = parseScene(std::string(kGrid2d) + kBasis + R"(
[[domain]]
shape = "ball"
center = [0, 0]
radius = 1

[[source]]
shape = "ball"
center = [0, -0.6]
radius = 0.15

[simulation]
integrator = "explicit"
)",
                                       "s.toml");
    ASSERT_EQ(scene.domain.size(), 1u);
    EXPECT_EQ(scene.domain[0].op, CsgOp::Union);
    EXPECT_EQ(scene.domain[0].center, (Vec3{0.0, 0.0, 0.0}));
    ASSERT_EQ(scene.sources.size(), 1u);
    EXPECT_EQ(scene.sources[0].shape.center, (Vec3{0.0, -0.6, 0.0}));
    EXPECT_EQ(scene.sources[0].density, SourceSpec{}.density);
    EXPECT_EQ(scene.sources[0].temperature, SourceSpec{}.temperature);
    EXPECT_EQ(scene.simulation.integrator, Integrator::Explicit);
    EXPECT_EQ(scene.simulation.dt, SimulationSpec{}.dt);
}

TEST(ModeRanges, ParsesListsAndSingleModes) {
    EXPECT_EQ(parseModeRanges("1-115,516-630", "k"),
              (std::vector<ModeRange>{{1, 115}, {516, 630}}));
    EXPECT_EQ(parseModeRanges("40", "k"), (std::vector<ModeRange>{{40, 40}}));
    EXPECT_EQ(parseModeRanges(" 3 - 5 , 6,8-8 ", "k"),
              (std::vector<ModeRange>{{3, 5}, {6, 6}, {8, 8}}));
}

TEST(ModeRanges, RejectsBadLists) {
    const char* bad[] = {"",   "  ",   "0-5",   "5-3", "1-10,5-20", "10,3", "1-",
                         "-3", "1,,2", "1-10,", "a",   "1.5",       "1 2",  "99999999999999"};
    for (const char* text : bad) {
        try {
            parseModeRanges(text, "[basis].modes");
            ADD_FAILURE() << "accepted \"" << text << "\"";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind("[basis].modes: ", 0), 0u) << e.what();
        }
    }
    try {
        parseModeRanges("1-10,5-20", "[basis].modes");
    } catch (const Error& e) {
        EXPECT_CONTAINS(e.what(), "overlaps");
    }
}

TEST_F(SceneLoaderTest, ModesStringErrorsNameTheKeyAndFile) {
    const std::string message = errorOf(std::string(kGrid2d) + "[basis]\nmodes = \"5-3\"\n");
    EXPECT_EQ(message.rfind("scenes/bad.toml: [basis].modes: ", 0), 0u) << message;
}

TEST_F(SceneLoaderTest, UnknownKeyIsNamedWithSuggestion) {
    const std::string message = errorOf(std::string(kGrid2d) + "[basis]\nvelocity_mode = 10\n");
    EXPECT_EQ(message.rfind("scenes/bad.toml: [basis].velocity_mode: unknown key", 0), 0u)
        << message;
    EXPECT_CONTAINS(message, "did you mean velocity_modes?");
}

TEST_F(SceneLoaderTest, UnknownTableAndShapeKeysAreNamed) {
    std::string message = errorOf(std::string(kGrid2d) + kBasis + "[grdi]\nx = 1\n");
    EXPECT_CONTAINS(message, "grdi: unknown table");
    EXPECT_CONTAINS(message, "did you mean grid?");

    message =
        errorOf(std::string(kGrid2d) + kBasis +
                "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\nradii = [1, 1]\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (ball).radii: not a key of a ball");

    message = errorOf(std::string(kGrid2d) + kBasis + "[output]\nframes = 3\nfps = 24\n");
    EXPECT_CONTAINS(message, "[output].fps: unknown key");
}

TEST_F(SceneLoaderTest, WrongTypeNamesKeyAndExpectedType) {
    std::string message = errorOf(std::string(kGrid2d) + kBasis + "[simulation]\ndt = \"fast\"\n");
    EXPECT_CONTAINS(message, "[simulation].dt: expected a number, got a string");

    // Floats where integers belong are errors, even when whole.
    message = errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 40.0\n");
    EXPECT_CONTAINS(message, "[basis].velocity_modes: expected an integer, got a floating-point");

    message =
        errorOf("[grid]\nresolution = [64, 64.5]\nbounds_min = [0, 0]\nbounds_max = [1, 1]\n" +
                std::string(kBasis));
    EXPECT_CONTAINS(message, "[grid].resolution[1]: expected an integer");

    message = errorOf(std::string(kGrid2d) + kBasis + "[simulation]\nintegrator = \"rk5\"\n");
    EXPECT_CONTAINS(message, "[simulation].integrator: unknown value \"rk5\"");
    EXPECT_CONTAINS(message, "did you mean rk4?");

    message =
        errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 4\neigensolver = \"arpack\"\n");
    EXPECT_CONTAINS(message, "[basis].eigensolver: unknown value \"arpack\"");
    EXPECT_CONTAINS(message, "expected auto, spectra or slepc");
}

TEST_F(SceneLoaderTest, ResolutionBelowTwoIsRejected) {
    const std::string message =
        errorOf("[grid]\nresolution = [64, 1]\nbounds_min = [0, 0]\nbounds_max = [1, 1]\n" +
                std::string(kBasis));
    EXPECT_EQ(message.rfind("scenes/bad.toml: [grid].resolution[1]: must be between 2 and", 0), 0u)
        << message;
}

TEST_F(SceneLoaderTest, ResolutionEntryCountIsChecked) {
    const std::string message =
        errorOf("[grid]\nresolution = [8, 8, 8, 8]\nbounds_min = [0, 0]\nbounds_max = [1, 1]\n" +
                std::string(kBasis));
    EXPECT_EQ(message.rfind("scenes/bad.toml: [grid].resolution: expected 2 or 3 integers, got 4 "
                            "entries",
                            0),
              0u)
        << message;
}

TEST_F(SceneLoaderTest, AbsurdlyLargeGridIsRejected) {
    const std::string message = errorOf(
        "[grid]\nresolution = [4096, 4096, 4096]\nbounds_min = [0, 0, 0]\n"
        "bounds_max = [1, 1, 1]\n" +
        std::string(kBasis));
    EXPECT_CONTAINS(message, "[grid].resolution");
    EXPECT_CONTAINS(message, "absurdly large");

    const std::string tooWide =
        errorOf("[grid]\nresolution = [100000, 4]\nbounds_min = [0, 0]\nbounds_max = [1, 1]\n" +
                std::string(kBasis));
    EXPECT_CONTAINS(tooWide, "[grid].resolution[0]");
}

TEST_F(SceneLoaderTest, InvertedBoundsAreRejected) {
    const std::string message =
        errorOf("[grid]\nresolution = [8, 8]\nbounds_min = [0, 1]\nbounds_max = [1, -1]\n" +
                std::string(kBasis));
    EXPECT_CONTAINS(message, "[grid].bounds_max");
    EXPECT_CONTAINS(message, "inverted bounds");
    EXPECT_CONTAINS(message, "axis y");
}

/// A 2D [grid] of 8 x 8 cells with the given bounds, and a basis.
std::string grid2d(const std::string& lo, const std::string& hi) {
    return "[grid]\nresolution = [8, 8]\nbounds_min = [" + lo + "]\nbounds_max = [" + hi + "]\n" +
           kBasis;
}

TEST_F(SceneLoaderTest, ExtremeBoundsAreRefusedAtLoad) {
    // These passed the loader and failed deep inside the eigensolver ("penalty to nan").
    std::string message = errorOf(grid2d("-1e300, 0", "1e300, 1"));
    EXPECT_CONTAINS(message,
                    "[grid].bounds_min/bounds_max: cells of 2.5e+299 along x are larger "
                    "than 1e+06");
    EXPECT_CONTAINS(message, "(line 4)");
    message = errorOf(grid2d("0, 0", "1e-200, 1e-200"));
    EXPECT_CONTAINS(message,
                    "[grid].bounds_min/bounds_max: cells of 1.25e-201 along x are smaller "
                    "than 1e-06");
    message = errorOf(grid2d("-1e308, 0", "1e308, 1"));
    EXPECT_CONTAINS(message,
                    "[grid].bounds_min/bounds_max: bounds_max - bounds_min along x is "
                    "not a finite number");
    message = errorOf(grid2d("0, 0", "8000, 4"));
    EXPECT_CONTAINS(message,
                    "[grid].bounds_min/bounds_max: cells are 2000 times longer along x "
                    "(1000) than along y (0.5); at most 1000");
    message = errorOf(grid2d("1e15, 0", "1.000000000000064e15, 64"));
    EXPECT_CONTAINS(message,
                    "[grid].bounds_max: the grid lies 1.3e+14 cells (of 8) from the "
                    "origin along x; at most 1e+12");

    // The limits themselves are accepted, in 3D too.
    EXPECT_EQ(errorOf(grid2d("0, 0", "8e-6, 8e-3")), "");
    EXPECT_EQ(errorOf(grid2d("-4e6, 0", "4e6, 8e3")), "");
    EXPECT_EQ(errorOf("[grid]\nresolution = [8, 8, 8]\nbounds_min = [0, 0, 0]\n"
                      "bounds_max = [8e-6, 8e-3, 8e-4]\n" +
                      std::string(kBasis)),
              "");
}

TEST_F(SceneLoaderTest, BoundsMustMatchDimension) {
    const std::string message =
        errorOf("[grid]\nresolution = [8, 8]\nbounds_min = [0, 0, 0]\nbounds_max = [1, 1]\n" +
                std::string(kBasis));
    EXPECT_CONTAINS(message, "[grid].bounds_min: expected 2 numbers");
}

TEST_F(SceneLoaderTest, CylinderIn2dIsRejected) {
    const std::string message =
        errorOf(std::string(kGrid2d) + kBasis +
                "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\n"
                "[[domain]]\nshape = \"cylinder\"\ncenter = [0, 0]\nradius = 1\n"
                "half_height = 1\n");
    EXPECT_CONTAINS(message, "[[domain]] #2 (cylinder).shape");
    EXPECT_CONTAINS(message, "3D only");
}

TEST_F(SceneLoaderTest, ShapeValuesAreValidated) {
    std::string message = errorOf(std::string(kGrid3d) + kBasis +
                                  "[[domain]]\nshape = \"torus\"\ncenter = [0, 0, 0]\n"
                                  "major_radius = 0.5\nminor_radius = 0.7\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (torus).minor_radius: must be less than major_radius");

    message = errorOf(std::string(kGrid3d) + kBasis +
                      "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.5\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (ball).center: expected 3 numbers");

    message = errorOf(std::string(kGrid2d) + kBasis +
                      "[[domain]]\nshape = \"box\"\nmin = [0, 0]\nmax = [1, 0]\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (box).max: must exceed min");

    message = errorOf(std::string(kGrid2d) + kBasis +
                      "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = -1\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (ball).radius: must be > 0");

    message =
        errorOf(std::string(kGrid2d) + kBasis + "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (ball).radius: missing required key");

    message = errorOf(std::string(kGrid3d) + kBasis +
                      "[[source]]\nshape = \"torus\"\ncenter = [0, 0, 0]\n"
                      "major_radius = 0.5\nminor_radius = 0.1\n");
    EXPECT_CONTAINS(message, "[[source]] #1 (torus).shape: a source must be a ball or a box");

    message = errorOf(std::string(kGrid3d) + kBasis +
                      "[[domain]]\nshape = \"mesh\"\n"
                      "file = \"missing.obj\"\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (mesh).file: no such file");

    message = errorOf(std::string(kGrid2d) + kBasis +
                      "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\n"
                      "op = \"subtract\"\n");
    EXPECT_CONTAINS(message, "[[domain]] #1 (ball).op");
}

TEST_F(SceneLoaderTest, MeshPathThatIsNotAFileSaysWhatItIs) {
    fs::create_directories(mDir / "folder.obj");
    ASSERT_EQ(::mkfifo((mDir / "pipe.obj").c_str(), 0600), 0);
    const auto meshScene = [](const std::string& file) {
        return std::string(kGrid3d) + kBasis + "[[domain]]\nshape = \"mesh\"\nfile = \"" + file +
               "\"\n";
    };
    std::string message = errorOf(meshScene("folder.obj"), mDir / "s.toml");
    EXPECT_CONTAINS(message, "[[domain]] #1 (mesh).file: " + (mDir / "folder.obj").string() +
                                 " is a directory, not an OBJ file");
    message = errorOf(meshScene("pipe.obj"), mDir / "s.toml");
    EXPECT_CONTAINS(message, "pipe.obj is a FIFO, not an OBJ file");
    message = errorOf(meshScene("missing.obj"), mDir / "s.toml");
    EXPECT_CONTAINS(message, "[[domain]] #1 (mesh).file: no such file: ");
}

TEST_F(SceneLoaderTest, BothVelocityModesAndModesIsAnError) {
    const std::string message =
        errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 10\nmodes = \"1-10\"\n");
    EXPECT_CONTAINS(message, "[basis].modes");
    EXPECT_CONTAINS(message, "velocity_modes");
    EXPECT_CONTAINS(message, "not both");
}

TEST_F(SceneLoaderTest, RequiredTablesAndKeys) {
    EXPECT_CONTAINS(errorOf(kBasis), "[grid]: missing required table");
    EXPECT_CONTAINS(errorOf(kGrid2d), "[basis]: missing required table");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + "[basis]\nscalar_modes = 3\n"),
                    "[basis]: missing velocity_modes");
    EXPECT_CONTAINS(
        errorOf("[grid]\nresolution = [8, 8]\nbounds_min = [0, 0]\n" + std::string(kBasis)),
        "[grid].bounds_max: missing required key");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 0\n"),
                    "[basis].velocity_modes: must be at least 1");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 100000\n"),
                    "[basis].velocity_modes: mode 100000 is beyond the discrete space");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + kBasis + "[domain]\nshape = \"ball\"\n"),
                    "[[domain]]: expected an array of tables");
}

TEST_F(SceneLoaderTest, RangeChecksOnScalars) {
    const std::string base = std::string(kGrid2d) + kBasis;
    EXPECT_CONTAINS(errorOf(base + "[simulation]\ndt = 0\n"), "[simulation].dt: must be > 0");
    EXPECT_CONTAINS(errorOf(base + "[simulation]\nviscosity = -1\n"),
                    "[simulation].viscosity: must be >= 0");
    EXPECT_CONTAINS(errorOf(base + "[simulation]\ndt = nan\n"), "[simulation].dt: must be finite");
    EXPECT_CONTAINS(errorOf(base + "[initial]\nvelocity = \"random\"\nseed = -1\n"),
                    "[initial].seed: must be at least 0");
    EXPECT_CONTAINS(errorOf(base + "[smoke]\nresolution_scale = 9\n"),
                    "[smoke].resolution_scale: must be between 1 and 8");
    EXPECT_CONTAINS(errorOf(base + "[smoke]\nadvection = \"bfecc\"\n"), "[smoke].advection");
    EXPECT_CONTAINS(errorOf(base + "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = "
                                   "0.1\nstart = 2.0\nend = 1.0\n"),
                    "end: must be later than start");
    EXPECT_CONTAINS(errorOf(base + "[simulation]\nbasis_precision = \"float8\"\n"),
                    "[simulation].basis_precision");
    EXPECT_CONTAINS(
        errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 4\nsubsamples = 17\n"),
        "[basis].subsamples: must be between 1 and 16");
    EXPECT_CONTAINS(
        errorOf(std::string(kGrid2d) + "[basis]\nvelocity_modes = 4\ncoefficients = \"packed\"\n"),
        "[basis].coefficients");
    EXPECT_CONTAINS(errorOf(base + "[output]\nframes = 0\n"),
                    "[output].frames: must be at least 1");
    EXPECT_CONTAINS(errorOf(base + "[output]\nsteps_per_frame = 9999999999\n"),
                    "[output].steps_per_frame: is too large");
}

TEST_F(SceneLoaderTest, MoreSourcesOrObstaclesThanTheRuntimeTakesAreRefusedAtLoad) {
    // They were refused only after the whole precompute, when the simulation was set up.
    const std::string source = "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\n";
    const std::string obstacle =
        "[[obstacle]]\nshape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0]]\n";
    std::string eight = std::string(kGrid2d) + kBasis;
    for (int i = 0; i < 8; ++i) eight += source + obstacle;
    const SceneSpec scene = parseScene(eight, "s.toml");
    EXPECT_EQ(scene.sources.size(), 8u);
    EXPECT_EQ(scene.obstacles.size(), 8u);

    std::string message = errorOf(eight + source);
    EXPECT_CONTAINS(message, "[[source]]: 9 entries; at most 8 sources take part in a simulation");
    EXPECT_CONTAINS(message, "(line 73)");  // the ninth entry
    message = errorOf(eight + obstacle);
    EXPECT_CONTAINS(message,
                    "[[obstacle]]: 9 entries; at most 8 obstacles take part in a simulation");
}

TEST_F(SceneLoaderTest, RandomInitialVelocityTakesEnergySeedAndBand) {
    const std::string base = std::string(kGrid2d) + kBasis + "[initial]\nvelocity = \"random\"\n";
    const SceneSpec all = parseScene(base + "energy = 0.5\nseed = 9\n", "s.toml");
    EXPECT_EQ(all.initial.energy, 0.5);
    EXPECT_EQ(all.initial.seed, 9u);
    EXPECT_FALSE(all.initial.band.has_value());
    const SceneSpec band = parseScene(base + "band = [3, 10]\n", "s.toml");
    ASSERT_TRUE(band.initial.band.has_value());
    EXPECT_EQ(*band.initial.band, (ModeRange{3, 10}));

    EXPECT_CONTAINS(errorOf(base + "energy = -1\n"), "[initial].energy: must be >= 0");
    EXPECT_CONTAINS(errorOf(base + "band = [0, 4]\n"), "[initial].band: modes are numbered from 1");
    EXPECT_CONTAINS(errorOf(base + "band = [5, 4]\n"), "[initial].band: ends before it starts");
    EXPECT_CONTAINS(errorOf(base + "band = [1, 11]\n"),
                    "[initial].band: mode 11 is beyond the basis ([basis] has 10");
    EXPECT_CONTAINS(errorOf(base + "band = 3\n"), "[initial].band: expected [first, last]");
    EXPECT_CONTAINS(errorOf(base + "band = [1, 2.5]\n"), "[initial].band[1]: expected an integer");
    EXPECT_CONTAINS(errorOf(base + "bnad = [1, 2]\n"),
                    "[initial].bnad: unknown key (did you mean band?)");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[1, 1.0]]\n"),
                    "[initial].amplitudes: not used with velocity = \"random\" (it takes energy, "
                    "seed and band)");
}

TEST_F(SceneLoaderTest, NonFiniteNumbersAreRefusedForEveryFloatKey) {
    // TOML spells them nan, inf and -inf; each float key names itself when given one.
    const std::string mhd = std::string(kGrid2d) + kBasis + "[simulation]\nmhd = true\n[initial]\n";
    const std::string vortex2 =
        std::string(kGrid2d) + kBasis + "[initial]\nvelocity = \"vortices\"\n[[initial.vortex]]\n";
    const std::string vortex3 =
        std::string(kGrid3d) + kBasis + "[initial]\nvelocity = \"vortices\"\n[[initial.vortex]]\n";
    const std::string source = std::string(kGrid2d) + kBasis + "[[source]]\nshape = \"ball\"\n";
    const std::string obstacle = std::string(kGrid2d) + kBasis + "[[obstacle]]\n";
    const std::string domain3 = std::string(kGrid3d) + kBasis + "[[domain]]\n";
    const std::pair<std::string, std::string> cases[] = {
        {"[grid]\nresolution = [8, 8]\nbounds_min = [0, X]\nbounds_max = [1, 1]\n" +
             std::string(kBasis),
         "[grid].bounds_min[1]"},
        {"[grid]\nresolution = [8, 8]\nbounds_min = [0, 0]\nbounds_max = [X, 1]\n" +
             std::string(kBasis),
         "[grid].bounds_max[0]"},
        {domain3 + "shape = \"ball\"\ncenter = [0, X, 0]\nradius = 1\n", "center[1]"},
        {domain3 + "shape = \"ball\"\ncenter = [0, 0, 0]\nradius = X\n", "(ball).radius"},
        {domain3 + "shape = \"box\"\nmin = [0, 0, X]\nmax = [1, 1, 1]\n", "(box).min[2]"},
        {domain3 + "shape = \"box\"\nmin = [0, 0, 0]\nmax = [1, X, 1]\n", "(box).max[1]"},
        {domain3 + "shape = \"ellipsoid\"\ncenter = [0, 0, 0]\nradii = [X, 1, 1]\n",
         "(ellipsoid).radii[0]"},
        {domain3 + "shape = \"cylinder\"\ncenter = [0, 0, 0]\nradius = 1\nhalf_height = X\n",
         "(cylinder).half_height"},
        {domain3 + "shape = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = X\nminor_radius = 0.1\n",
         "(torus).major_radius"},
        {domain3 + "shape = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 1\nminor_radius = X\n",
         "(torus).minor_radius"},
        {std::string(kGrid2d) + kBasis + "[simulation]\ndt = X\n", "[simulation].dt"},
        {std::string(kGrid2d) + kBasis + "[simulation]\nviscosity = X\n", "[simulation].viscosity"},
        {std::string(kGrid2d) + kBasis + "[simulation]\nalpha = X\n", "[simulation].alpha"},
        {std::string(kGrid2d) + kBasis + "[simulation]\nmhd = true\nmagnetic_diffusivity = X\n",
         "[simulation].magnetic_diffusivity"},
        {std::string(kGrid2d) + kBasis + "[initial]\nvelocity = \"random\"\nenergy = X\n",
         "[initial].energy"},
        {std::string(kGrid2d) + kBasis + "[initial]\nvelocity = \"modes\"\namplitudes = [[1, X]]\n",
         "[initial].amplitudes[0][1]"},
        {mhd + "magnetic_energy = X\n", "[initial].magnetic_energy"},
        {mhd + "magnetic = \"uniform\"\nmagnetic_direction = [X, 1]\n",
         "[initial].magnetic_direction[0]"},
        {mhd + "magnetic = \"uniform\"\nmagnetic_direction = [1, 0]\nmagnetic_strength = X\n",
         "[initial].magnetic_strength"},
        {mhd + "magnetic = \"uniform\"\nmagnetic_direction = [1, 0]\nmagnetic_wall_layer = X\n",
         "[initial].magnetic_wall_layer"},
        {vortex2 + "center = [X, 0]\nstrength = 1\nradius = 0.1\n",
         "[[initial.vortex]] #1.center[0]"},
        {vortex2 + "center = [0, 0]\nstrength = X\nradius = 0.1\n",
         "[[initial.vortex]] #1.strength"},
        {vortex2 + "center = [0, 0]\nstrength = 1\nradius = X\n", "[[initial.vortex]] #1.radius"},
        {vortex3 + "center = [0, 0, 0]\nnormal = [0, X, 1]\nring_radius = 0.5\nradius = 0.1\n"
                   "strength = 1\n",
         "[[initial.vortex]] #1.normal[1]"},
        {vortex3 + "center = [0, 0, 0]\nnormal = [0, 0, 1]\nring_radius = X\nradius = 0.1\n"
                   "strength = 1\n",
         "[[initial.vortex]] #1.ring_radius"},
        {source + "center = [0, 0]\nradius = 0.1\ndensity = X\n", "(ball).density"},
        {source + "center = [0, 0]\nradius = 0.1\ntemperature = X\n", "(ball).temperature"},
        {source + "center = [0, 0]\nradius = 0.1\nstart = X\n", "(ball).start"},
        {source + "center = [0, 0]\nradius = 0.1\nend = X\n", "(ball).end"},
        {obstacle + "shape = \"ball\"\nradius = X\npath = [[0, 0, 0]]\n", "[[obstacle]] #1.radius"},
        {obstacle + "shape = \"box\"\nhalf_size = [0.1, X]\npath = [[0, 0, 0]]\n",
         "[[obstacle]] #1.half_size[1]"},
        {obstacle + "shape = \"capsule\"\nradius = 0.1\naxis = [X, 0]\npath = [[0, 0, 0]]\n",
         "[[obstacle]] #1.axis[0]"},
        {obstacle + "shape = \"ball\"\nradius = 0.1\npath = [[X, 0, 0]]\n",
         "[[obstacle]] #1.path time"},
        {obstacle + "shape = \"ball\"\nradius = 0.1\npath = [[0, 0, X]]\n", "[[obstacle]] #1.path"},
        {std::string(kGrid2d) + kBasis + "[smoke]\nbuoyancy = X\n", "[smoke].buoyancy"},
    };
    for (const auto& [text, key] : cases) {
        const std::size_t x = text.find('X');
        ASSERT_NE(x, std::string::npos) << key;
        for (const std::string value : {"nan", "inf", "-inf"}) {
            const std::string message = errorOf(text.substr(0, x) + value + text.substr(x + 1));
            EXPECT_CONTAINS(message, key + ": must be finite, got " + value);
        }
    }
    // Beyond a double's range TOML itself refuses the number, with its line.
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + kBasis + "[simulation]\ndt = 1e400\n"),
                    "line 10, column");
}

TEST_F(SceneLoaderTest, AbsurdInitialSpeedsAreRefused) {
    // energy = 1e300 was accepted and later blamed on dt ("energy = inf"). Energies are ½∫|u|²
    // over the grid's box (2.2 x 2.2 x 1 here), so the cap is a mean speed, scale-free in space.
    const std::string base = std::string(kGrid2d) + kBasis;
    const double volume = 2.2 * 2.2;
    const auto energyAt = [&](double speed) {
        return formatNumberForTest(0.5 * speed * speed * volume);
    };
    EXPECT_EQ(
        errorOf(base + "[initial]\nvelocity = \"random\"\nenergy = " + energyAt(0.99e6) + "\n"),
        "");
    std::string message = errorOf(base + "[initial]\nvelocity = \"random\"\nenergy = 1e300\n");
    EXPECT_CONTAINS(message,
                    "[initial].energy: 1e+300 is a mean speed of 6.4e+149 (sqrt(2 energy / "
                    "grid volume 4.8)); at most 1e+06 scene units per unit time (line 11)");
    message =
        errorOf(base + "[initial]\nvelocity = \"random\"\nenergy = " + energyAt(1.01e6) + "\n");
    EXPECT_CONTAINS(message, "[initial].energy: ");
    EXPECT_CONTAINS(message, "is a mean speed of 1e+06");

    message =
        errorOf(base + "[initial]\nvelocity = \"modes\"\namplitudes = [[1, 1], [2, 1e200]]\n");
    EXPECT_CONTAINS(message, "[initial].amplitudes: ½Σa² = inf is a mean speed of inf");
    const std::string mhd = base + "[simulation]\nmhd = true\n[initial]\n";
    message = errorOf(mhd + "magnetic_energy = 1e300\n");
    EXPECT_CONTAINS(message, "[initial].magnetic_energy: 1e+300 is a mean field of 6.4e+149");
    message = errorOf(
        mhd + "magnetic = \"uniform\"\nmagnetic_direction = [1, 0]\nmagnetic_strength = 2e6\n");
    EXPECT_CONTAINS(message, "[initial].magnetic_strength: 2e+06 is beyond 1e+06");
    message = errorOf(base +
                      "[initial]\nvelocity = \"vortices\"\n[[initial.vortex]]\ncenter = [0, 0]\n"
                      "strength = 1e300\nradius = 0.1\n");
    EXPECT_CONTAINS(
        message,
        "[[initial.vortex]] #1.strength: magnitude 1e+300 is beyond 2.2e+06 (1e+06 scene "
        "units per unit time times the grid's longest side, 2.2)");
}

TEST_F(SceneLoaderTest, MagneticFieldIsRandomOrUniformAndChecked) {
    const std::string base =
        std::string(kGrid2d) + kBasis + "[simulation]\nmhd = true\n[initial]\n";
    const SceneSpec random =
        parseScene(base + "magnetic_energy = 0.5\nmagnetic_seed = 7\n", "s.toml");
    EXPECT_EQ(random.initial.magnetic, InitialMagnetic::Random);
    EXPECT_EQ(random.initial.magneticEnergy, 0.5);
    EXPECT_EQ(random.initial.magneticSeed, 7u);
    const std::string uniform = base + "magnetic = \"uniform\"\n";
    const SceneSpec scene =
        parseScene(uniform + "magnetic_direction = [1, 0.5]\nmagnetic_strength = 2.5\n", "s.toml");
    EXPECT_EQ(scene.initial.magnetic, InitialMagnetic::Uniform);
    EXPECT_EQ(scene.initial.magneticDirection, (Vec3{1.0, 0.5, 0.0}));
    EXPECT_EQ(scene.initial.magneticStrength, 2.5);
    EXPECT_EQ(scene.initial.magneticWallLayer, 0.0) << "0: the basis's own wavelength";
    const SceneSpec defaults =
        parseScene(uniform + "magnetic_direction = [0, 1]\nmagnetic_wall_layer = 0.4\n", "s.toml");
    EXPECT_EQ(defaults.initial.magneticStrength, 1.0);
    EXPECT_EQ(defaults.initial.magneticWallLayer, 0.4);

    EXPECT_CONTAINS(errorOf(base + "magnetic = \"uniforn\"\n"),
                    "[initial].magnetic: unknown value \"uniforn\" (did you mean uniform?)");
    EXPECT_CONTAINS(errorOf(uniform), "[initial].magnetic_direction: missing required key");
    EXPECT_CONTAINS(errorOf(uniform + "magnetic_direction = [1, 0, 0]\n"),
                    "[initial].magnetic_direction: expected 2 numbers (the scene is 2D)");
    EXPECT_CONTAINS(errorOf(uniform + "magnetic_direction = [0, 0]\n"),
                    "[initial].magnetic_direction: must be a non-zero vector");
    EXPECT_CONTAINS(errorOf(uniform + "magnetic_direction = [1, 0]\nmagnetic_strength = -1\n"),
                    "[initial].magnetic_strength: must be >= 0");
    EXPECT_CONTAINS(errorOf(uniform + "magnetic_direction = [1, 0]\nmagnetic_energy = 1\n"),
                    "[initial].magnetic_energy: not used with magnetic = \"uniform\" (it takes "
                    "magnetic_direction, magnetic_strength and magnetic_wall_layer)");
    EXPECT_CONTAINS(errorOf(uniform + "magnetic_direction = [1, 0]\nmagnetic_wall_layer = 0\n"),
                    "[initial].magnetic_wall_layer: must be > 0");
    EXPECT_CONTAINS(errorOf(base + "magnetic_strength = 1\n"),
                    "[initial].magnetic_strength: not used with magnetic = \"random\"");
    EXPECT_CONTAINS(errorOf(base + "magnetic_directoin = [1, 0]\n"),
                    "[initial].magnetic_directoin: unknown key (did you mean magnetic_direction?)");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + kBasis + "[initial]\nmagnetic = \"uniform\"\n"),
                    "[initial].magnetic: only used with [simulation] mhd = true");
}

TEST_F(SceneLoaderTest, ForcingHoldsModesByPositionOrWaveNumber) {
    const std::string base = std::string(kGrid2d) + kBasis;
    const SceneSpec none = parseScene(base, "s.toml");
    EXPECT_FALSE(none.forcing.holds());
    const SceneSpec byPosition = parseScene(base + "[forcing]\nhold_modes = \"1-3,5\"\n", "s.toml");
    EXPECT_EQ(byPosition.forcing.holdModes, (std::vector<ModeRange>{{1, 3}, {5, 5}}));
    EXPECT_TRUE(byPosition.forcing.holds());
    const SceneSpec byKappa = parseScene(base + "[forcing]\nhold_below_kappa = 2.0\n", "s.toml");
    EXPECT_EQ(byKappa.forcing.holdBelowKappa, 2.0);
    EXPECT_TRUE(byKappa.forcing.holdModes.empty());

    EXPECT_CONTAINS(errorOf(base + "[forcing]\n"),
                    "[forcing]: missing hold_modes (e.g. \"1-5\") or hold_below_kappa (e.g. 2.0)");
    EXPECT_CONTAINS(
        errorOf(base + "[forcing]\nhold_modes = \"1\"\nhold_below_kappa = 2.0\n"),
        "[forcing].hold_below_kappa: give either hold_modes or hold_below_kappa, not both");
    EXPECT_CONTAINS(errorOf(base + "[forcing]\nhold_below_kappa = 0\n"),
                    "[forcing].hold_below_kappa: must be > 0");
    EXPECT_CONTAINS(errorOf(base + "[forcing]\nhold_modes = \"3-1\"\n"),
                    "[forcing].hold_modes: bad mode list");
    EXPECT_CONTAINS(
        errorOf(base + "[forcing]\nhold_modes = \"9-11\"\n"),
        "[forcing].hold_modes: mode 11 is beyond the basis ([basis] has 10 velocity modes)");
    // Every mode, however the ranges split them: refused at load, not after the precompute.
    for (const char* all : {"1-10", "1-5,6-10", "1,2-9,10", "1-4,5,6-10"})
        EXPECT_CONTAINS(errorOf(base + "[forcing]\nhold_modes = \"" + all + "\"\n"),
                        "[forcing].hold_modes: holds every mode of the basis: nothing would move");
    for (const char* some : {"1-9", "2-10", "1-4,6-10", "1,3-10"})
        EXPECT_TRUE(parseScene(base + "[forcing]\nhold_modes = \"" + some + "\"\n", "s.toml")
                        .forcing.holds())
            << some;
    EXPECT_CONTAINS(errorOf(base + "[forcing]\nhold = 2\n"), "[forcing].hold: unknown key");
    EXPECT_CONTAINS(errorOf(base + "[simulation]\nmhd = true\n[forcing]\nhold_modes = \"1\"\n"),
                    "[forcing]: holds velocity modes of the fluid model; it cannot be combined "
                    "with [simulation] mhd");
    EXPECT_CONTAINS(errorOf(base + "[forcng]\n"), "unknown table (did you mean forcing?)");
}

TEST_F(SceneLoaderTest, TheLinearizedRuleIsForFluids) {
    const std::string base = std::string(kGrid2d) + kBasis + "[simulation]\n";
    EXPECT_EQ(parseScene(base + "integrator = \"linearized\"\n", "s.toml").simulation.integrator,
              Integrator::Linearized);
    EXPECT_CONTAINS(
        errorOf(base + "integrator = \"linearized\"\nmhd = true\n"),
        "[simulation].integrator: linearized is for fluids; MHD takes midpoint (or trapezoidal, "
        "explicit, rk4)");
}

TEST_F(SceneLoaderTest, ModalAmplitudesAreRequiredAndChecked) {
    const std::string base = std::string(kGrid2d) + kBasis + "[initial]\nvelocity = \"modes\"\n";
    const SceneSpec scene =
        parseScene(base + "amplitudes = [[1, 0.5], [3, -0.2], [10, 2]]\n", "s.toml");
    const std::vector<std::pair<int, double>> expected{{1, 0.5}, {3, -0.2}, {10, 2.0}};
    EXPECT_EQ(scene.initial.amplitudes, expected);

    EXPECT_CONTAINS(errorOf(base),
                    "[initial].amplitudes: missing required key for velocity = \"modes\"");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = []\n"),
                    "[initial].amplitudes: expected a non-empty array");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [1, 0.5]\n"),
                    "[initial].amplitudes[0]: expected a [mode, amplitude] pair, got an integer");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[1, 0.5, 2]]\n"),
                    "[initial].amplitudes[0]: expected a [mode, amplitude] pair, got 3 entries");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[0, 0.5]]\n"),
                    "[initial].amplitudes[0]: mode 0 is outside the basis (modes 1 to 10)");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[2, 1], [11, 0.5]]\n"),
                    "[initial].amplitudes[1]: mode 11 is outside the basis");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[2, 1], [2, 0.5]]\n"),
                    "[initial].amplitudes[1]: mode 2 is given twice");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[1.5, 1]]\n"),
                    "[initial].amplitudes[0][0]: expected an integer");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[1, \"big\"]]\n"),
                    "[initial].amplitudes[0][1]: expected a number, got a string");
    EXPECT_CONTAINS(errorOf(base + "amplitudes = [[1, 1]]\nseed = 3\n"),
                    "[initial].seed: not used with velocity = \"modes\" (it takes amplitudes)");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + kBasis + "[initial]\nenergy = 1\n"),
                    "[initial].energy: not used with velocity = \"zero\" (it takes no other key)");
}

TEST_F(SceneLoaderTest, VorticesAreReadIn2dAnd3d) {
    const std::string base2 =
        std::string(kGrid2d) + kBasis + "[initial]\nvelocity = \"vortices\"\n";
    const SceneSpec two = parseScene(base2 + R"(
[[initial.vortex]]
center = [0.1, -0.2]
strength = 2
radius = 0.1
[[initial.vortex]]
center = [-0.3, 0.0]
strength = -1.5
radius = 0.2
)",
                                     "s.toml");
    EXPECT_EQ(two.initial.energy, 0.0) << "no energy key: keep the projection's own energy";
    ASSERT_EQ(two.initial.vortices.size(), 2u);
    EXPECT_EQ(two.initial.vortices[0].center, (Vec3{0.1, -0.2, 0.0}));
    EXPECT_EQ(two.initial.vortices[0].strength, 2.0);
    EXPECT_EQ(two.initial.vortices[0].radius, 0.1);
    EXPECT_EQ(two.initial.vortices[1].strength, -1.5);

    const std::string vortex = "[[initial.vortex]]\ncenter = [0, 0]\nstrength = 1\nradius = 0.1\n";
    EXPECT_CONTAINS(errorOf(base2), "[[initial.vortex]]: missing");
    EXPECT_CONTAINS(errorOf(base2 + "vortex = 3\n"),
                    "[[initial.vortex]]: expected an array of tables");
    EXPECT_CONTAINS(
        errorOf(base2 + "energy = 2\nseed = 1\n" + vortex),
        "[initial].seed: not used with velocity = \"vortices\" (it takes vortex and energy)");
    EXPECT_CONTAINS(errorOf(base2 + "[[initial.vortex]]\ncenter = [0, 0]\nradius = 0.1\n"),
                    "[[initial.vortex]] #1.strength: missing required key");
    EXPECT_CONTAINS(
        errorOf(base2 + vortex + "[[initial.vortex]]\ncenter = [0, 0]\nstrength = 1\nradius = 0\n"),
        "[[initial.vortex]] #2.radius: must be > 0");
    EXPECT_CONTAINS(
        errorOf(base2 + "[[initial.vortex]]\ncenter = [0, 0, 0]\nstrength = 1\nradius = 0.1\n"),
        "[[initial.vortex]] #1.center: expected 2 numbers (the scene is 2D)");
    EXPECT_CONTAINS(errorOf(base2 + vortex + "strenght = 2\n"),
                    "[[initial.vortex]] #1.strenght: unknown key (did you mean strength?)");
    EXPECT_CONTAINS(errorOf(base2 + vortex + "ring_radius = 0.5\n"),
                    "[[initial.vortex]] #1.ring_radius: only 3D vortex rings take it");
    EXPECT_CONTAINS(
        errorOf(base2 + "[[initial.vortex]]\ncenter = [0, 0]\nstrength = \"big\"\nradius = 0.1\n"),
        "[[initial.vortex]] #1.strength: expected a number, got a string");

    const std::string base3 =
        std::string(kGrid3d) + kBasis + "[initial]\nvelocity = \"vortices\"\nenergy = 0.7\n";
    const std::string ring =
        "[[initial.vortex]]\ncenter = [0, 0, 0]\nring_radius = 0.4\nradius = 0.1\nstrength = 3\n";
    const SceneSpec three = parseScene(base3 + ring + "normal = [1, 0, 0]\n", "s.toml");
    EXPECT_EQ(three.initial.energy, 0.7);
    ASSERT_EQ(three.initial.vortices.size(), 1u);
    EXPECT_EQ(three.initial.vortices[0].normal, (Vec3{1.0, 0.0, 0.0}));
    EXPECT_EQ(three.initial.vortices[0].ringRadius, 0.4);
    EXPECT_CONTAINS(errorOf(base3 + ring), "[[initial.vortex]] #1.normal: missing required key");
    EXPECT_CONTAINS(errorOf(base3 + ring + "normal = [0, 0, 0]\n"),
                    "[[initial.vortex]] #1.normal: must be a non-zero vector");
    EXPECT_CONTAINS(errorOf(base3 + "[[initial.vortex]]\ncenter = [0, 0, 0]\nnormal = [0, 0, "
                                    "1]\nradius = 0.1\nstrength = 3\n"),
                    "[[initial.vortex]] #1.ring_radius: missing required key");
}

TEST_F(SceneLoaderTest, SyntaxErrorGivesFileAndLine) {
    const std::string message =
        errorOf("[grid]\nresolution = [64, 64]\nbounds_min = [0, 0\n", "scenes/broken.toml");
    EXPECT_EQ(message.rfind("scenes/broken.toml: line ", 0), 0u) << message;
    EXPECT_CONTAINS(message, "syntax error");

    const std::string second = errorOf("[grid]\nresolution = = 3\n", "x.toml");
    EXPECT_EQ(second.rfind("x.toml: line 2,", 0), 0u) << second;
}

TEST_F(SceneLoaderTest, MissingFileGivesClearMessage) {
    try {
        loadScene(mDir / "nope.toml");
        FAIL() << "loaded a missing file";
    } catch (const Error& e) {
        EXPECT_CONTAINS(e.what(), "nope.toml");
        EXPECT_CONTAINS(e.what(), "no such scene file");
    }
    try {
        loadScene(mDir);
        FAIL() << "loaded a folder";
    } catch (const Error& e) {
        EXPECT_CONTAINS(e.what(), "not a scene file");
    }
}

TEST_F(SceneLoaderTest, NonRegularFilesAreRefusedBeforeReading) {
    // /dev/zero never ends: read whole, it grew until the kernel killed the process.
    const auto expectRefused = [](const fs::path& file, const std::string& kind) {
        try {
            loadScene(file);
            ADD_FAILURE() << "loaded " << file;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
            EXPECT_CONTAINS(e.what(), kind);
        }
    };
    expectRefused("/dev/zero", "is a character device, not a scene file");
    expectRefused(mDir, "is a directory, not a scene file");
    const fs::path fifo = mDir / "pipe.toml";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expectRefused(fifo, "is a FIFO, not a scene file");  // opening it would wait for a writer
    fs::create_symlink("/dev/zero", mDir / "zero.toml");
    expectRefused(mDir / "zero.toml", "is a character device");
}

TEST_F(SceneLoaderTest, OversizedSceneFileIsRefusedBeforeReading) {
    const fs::path file = write("huge.toml", std::string(kGrid2d) + kBasis);
    fs::resize_file(file, kMaxSceneFileBytes + 1);  // sparse: no disk space used
    try {
        loadScene(file);
        FAIL() << "loaded a file of " << fs::file_size(file) << " bytes";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
        EXPECT_CONTAINS(e.what(), std::to_string(kMaxSceneFileBytes + 1) + " bytes");
        EXPECT_CONTAINS(e.what(), "at most " + std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
    }
    // The same limit holds for text already in memory.
    EXPECT_CONTAINS(errorOf(std::string(kMaxSceneFileBytes + 1, '#')),
                    "too large for a scene file");
}

TEST_F(SceneLoaderTest, ErrorsCarryTheLine) {
    const std::string message =
        errorOf(std::string(kGrid2d) + kBasis + "[simulation]\n\ndt = -1\n");
    // kGrid2d starts with a blank line: [grid] is line 2, so dt sits on line 11.
    EXPECT_CONTAINS(message, "(line 11)");
}

TEST_F(SceneLoaderTest, DeeplyNestedTablesAreRefusedNotACrash) {
    // toml++ walks nested tables recursively: [a.a.a...] 100000 deep overflowed the stack.
    std::string deep = "[a";
    for (int i = 0; i < 100000; ++i) deep += ".a";
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + kBasis + deep + "]\n"),
                    "scenes/bad.toml: line 9: 100000 dots on one line");
    // At the limit, on the three lines a nesting can span, parsing ends in a plain message.
    std::string header = "[a", key = "b", inner = "{c";
    for (int i = 0; i < kMaxDotsPerLine; ++i) header += ".a", key += ".b", inner += ".c";
    const std::string limit = header + "]\n" + key + " = [\n" + inner + " = 1}]\n";
    EXPECT_CONTAINS(errorOf(limit), "a: unknown table");
    // Long arrays of numbers fit, over several lines if need be.
    std::string path = "[[obstacle]]\nshape = \"ball\"\nradius = 0.1\npath = [\n";
    for (int i = 0; i < 3000; ++i)
        path.append("[").append(std::to_string(i)).append(".5, 0.25, 0.5],\n");
    EXPECT_EQ(errorOf(std::string(kGrid2d) + kBasis + path + "]\n"), "");
}

TEST_F(SceneLoaderTest, FileTextInMessagesIsPrintableAndShort) {
    // TOML escapes let a key or a value hold terminal commands; they were printed as they were.
    const std::string base = std::string(kGrid2d) + kBasis;
    std::string message = errorOf(base + "[output]\n\"\\u001b[2J\" = 1\n");
    EXPECT_CONTAINS(message, "[output].\\x1b[2J: unknown key");
    EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
    message = errorOf(base + "\"\\u001b]0;owned\\u0007\" = 1\n");
    EXPECT_CONTAINS(message, "\\x1b]0;owned\\x07: unknown key");
    message = errorOf(std::string(kGrid2d) + "[basis]\nmodes = \"1-3\\u001b[2J\"\n");
    EXPECT_CONTAINS(message, "bad mode list \"1-3\\x1b[2J\": unexpected character '\\x1b'");
    EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
    message = errorOf(base + "[simulation]\nintegrator = \"\\u009b31m\"\n");
    EXPECT_CONTAINS(message, "unknown value \"\\xc2\\x9b31m\"");

    // A megabyte-long value or key is cut, and a suggestion is not searched for in it.
    const std::string huge(1 << 20, '7');
    message = errorOf(std::string(kGrid2d) + "[basis]\nmodes = \"1-" + huge + "\"\n");
    EXPECT_LT(message.size(), 400u) << message.size() << " characters";
    EXPECT_CONTAINS(message, "...");
    message = errorOf(base + "[output]\n" + std::string(1 << 20, 'f') + " = 1\n");
    EXPECT_LT(message.size(), 400u) << message.size() << " characters";
    message = errorOf(base + "[simulation]\nintegrator = \"" + huge + "\"\n");
    EXPECT_LT(message.size(), 400u) << message.size() << " characters";
    EXPECT_CONTAINS(parseModeRangesError("1-3\x1b"), "\\x1b");
}

TEST_F(SceneLoaderTest, HostileValuesGetMessagesNamingTheKey) {
    const std::string base = std::string(kGrid2d) + kBasis;
    // Integers beyond their range.
    EXPECT_CONTAINS(errorOf("[grid]\nresolution = [9223372036854775807, 8]\nbounds_min = [0, 0]\n"
                            "bounds_max = [1, 1]\n" +
                            std::string(kBasis)),
                    "[grid].resolution[0]: must be between 2 and 4096, got 9223372036854775807");
    EXPECT_CONTAINS(errorOf("[grid]\nresolution = [9223372036854775808, 8]\n"),
                    "line 2, column");  // TOML refuses it: not representable in 64 bits
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + "[basis]\nmodes = \"1-2147483647\"\n"),
                    "[basis].modes: mode 2147483647 is beyond the discrete space");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + "[basis]\nmodes = \"1-2147483648\"\n"),
                    "[basis].modes: bad mode list \"1-2147483648\": mode number at position 3 "
                    "is too large");
    EXPECT_CONTAINS(errorOf(base + "[initial]\nvelocity = \"random\"\nband = [1, 4294967297]\n"),
                    "[initial].band: mode 4294967297 is beyond the basis");
    EXPECT_CONTAINS(errorOf(base + "[simulation]\nmhd = true\n[initial]\nmagnetic_seed = -3\n"),
                    "[initial].magnetic_seed: must be at least 0, got -3");
    // frames x steps_per_frame is the step count, an int.
    EXPECT_CONTAINS(errorOf(base + "[output]\nframes = 100000\nsteps_per_frame = 100000\n"),
                    "[output].steps_per_frame: frames x steps_per_frame = 10000000000 steps, "
                    "more than 2147483647");
    // Negative zero is not a size.
    EXPECT_CONTAINS(
        errorOf(base + "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = -0.0\n"),
        "[[domain]] #1 (ball).radius: must be > 0, got -0");
    EXPECT_CONTAINS(
        errorOf("[grid]\nresolution = [8, 8]\nbounds_min = [-0.0, 0]\nbounds_max = [0.0, 1]\n" +
                std::string(kBasis)),
        "[grid].bounds_max: must exceed bounds_min on every axis");
    // Huge arrays are counted, not echoed.
    std::string many = "[grid]\nresolution = [";
    for (int i = 0; i < 100000; ++i) many += "8, ";
    EXPECT_CONTAINS(errorOf(many + "8]\n"),
                    "[grid].resolution: expected 2 or 3 integers, got "
                    "100001 entries");
    // An empty file, and arrays of tables where tables belong.
    EXPECT_CONTAINS(errorOf(""), "scenes/bad.toml: [grid]: missing required table");
    EXPECT_CONTAINS(errorOf("[[grid]]\nresolution = [8, 8]\n"),
                    "[grid]: expected a table, got an array (line 1)");
    EXPECT_CONTAINS(errorOf(std::string(kGrid2d) + "[[basis]]\nvelocity_modes = 4\n"),
                    "[basis]: expected a table, got an array");
    EXPECT_CONTAINS(errorOf(base + "[[initial]]\nvelocity = \"zero\"\n"),
                    "[initial]: expected a table, got an array");
    EXPECT_CONTAINS(errorOf(base + "[initial]\nvelocity = \"vortices\"\n[initial.vortex]\n"
                                   "center = [0, 0]\n"),
                    "[[initial.vortex]]: expected an array of tables");
}

TEST(SceneKeywords, MatchTheFileSpelling) {
    EXPECT_EQ(sceneKeyword(ShapeKind::Torus), "torus");
    EXPECT_EQ(sceneKeyword(CsgOp::Subtract), "subtract");
    EXPECT_EQ(sceneKeyword(ScalarBoundary::Dirichlet), "dirichlet");
    EXPECT_EQ(sceneKeyword(WallKind::FreeSlip), "free-slip");
    EXPECT_EQ(sceneKeyword(BoundaryTreatment::CutCell), "cut-cell");
    EXPECT_EQ(sceneKeyword(Integrator::Rk4), "rk4");
    EXPECT_EQ(sceneKeyword(CoefficientStorage::TensorFree), "tensor-free");
    EXPECT_EQ(sceneKeyword(InitialVelocity::Vortices), "vortices");
}

TEST(ExampleScenes, EveryRepositorySceneLoads) {
    const fs::path folder = fs::path(MODEFLOW_SOURCE_DIR) / "scenes";
    ASSERT_TRUE(fs::is_directory(folder)) << folder;
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        if (entry.path().extension() != ".toml") continue;
        ++count;
        SCOPED_TRACE(entry.path().string());
        try {
            const SceneSpec scene = loadScene(entry.path());
            EXPECT_EQ(scene.name, entry.path().stem().string());
            EXPECT_GE(scene.basis.velocityCount(), 1);
        } catch (const Error& e) {
            ADD_FAILURE() << e.what();
        }
    }
    EXPECT_GE(count, 15);  // scenes/, scenes/bench/, scenes/seed/

    const SceneSpec def = loadScene(folder / "default.toml");
    EXPECT_EQ(def.grid.dim, 2);
    EXPECT_EQ(def.grid.resolution, (std::array<int, 3>{128, 128, 1}));
    EXPECT_EQ(def.basis.velocityCount(), 40);
    EXPECT_EQ(def.basis.scalarModes, 20);
    EXPECT_FALSE(def.sources.empty());
    EXPECT_GT(def.smoke.buoyancy, 0.0);
}

}  // namespace
}  // namespace modeflow

namespace modeflow {
namespace {

TEST(SceneLoaderPeriodic, PeriodicFlagsAreOnePerAxisAndDefaultToWalls) {
    const std::string grid =
        "[grid]\nresolution = [8, 8]\nbounds_min = [0, 0]\nbounds_max = [1, 1]\n";
    const SceneSpec walls = parseScene(grid + "[basis]\nvelocity_modes = 4\n", "walls.toml");
    EXPECT_FALSE(walls.grid.anyPeriodic());
    const SceneSpec explicitWalls =
        parseScene(grid + "periodic = [false, false]\n[basis]\nvelocity_modes = 4\n", "walls.toml");
    EXPECT_EQ(explicitWalls.grid, walls.grid);
    const auto refused = [&](const std::string& flags, const std::string& needle) {
        try {
            parseScene(grid + "periodic = " + flags + "\n[basis]\nvelocity_modes = 4\n", "p.toml");
            ADD_FAILURE() << "accepted periodic = " << flags;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    refused("[true]", "[grid].periodic: expected 2 booleans");
    refused("[true, false, true]", "expected 2 booleans");
    refused("true", "expected 2 booleans");
    refused("[1, 0]", "[grid].periodic[0]: expected true or false");
}

TEST(SceneLoaderPeriodic, PeriodicAxesAreAcceptedAndCountTheirFacesOnce) {
    const SceneSpec channel = parseScene(
        "[grid]\nresolution = [8, 4]\nbounds_min = [0, 0]\nbounds_max = [2, 1]\nperiodic = [true, "
        "false]\n"
        "[basis]\nvelocity_modes = 4\n",
        "channel.toml");
    EXPECT_EQ(channel.grid.periodic, (std::array<bool, 3>{true, false, false}));
    const SceneSpec slab = parseScene(
        "[grid]\nresolution = [4, 4, 4]\nbounds_min = [0, 0, 0]\nbounds_max = [1, 1, 1]\n"
        "periodic = [true, false, true]\n[basis]\nvelocity_modes = 4\n",
        "slab.toml");
    EXPECT_EQ(slab.grid.periodic, (std::array<bool, 3>{true, false, true}));
    // A 4 × 4 torus has 32 faces (a walled 4 × 4 box 40): mode 36 lies beyond it.
    const std::string torus =
        "[grid]\nresolution = [4, 4]\nbounds_min = [0, 0]\nbounds_max = [1, 1]\n";
    EXPECT_NO_THROW(
        parseScene(torus + "[basis]\nvelocity_modes = 36\nscalar_modes = 0\n", "box.toml"));
    try {
        parseScene(
            torus + "periodic = [true, true]\n[basis]\nvelocity_modes = 36\nscalar_modes = 0\n",
            "torus.toml");
        ADD_FAILURE() << "mode 36 of a 4 x 4 torus accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the grid has only 32 faces"), std::string::npos)
            << e.what();
    }
}

// ---- surface scenes ([surface]) -----------------------------------------------------------------

constexpr const char* kSurface = "[surface]\nmesh = \"meshes/ball.obj\"\n";

TEST_F(SceneLoaderTest, SurfaceSceneReadsItsMeshAndThreeDimensionalSources) {
    write("meshes/ball.obj", "v 0 0 0\n");
    const fs::path file = write("ball_surface.toml", std::string(kSurface) + R"(
[basis]
velocity_modes = 12
scalar_modes = 20

[initial]
velocity = "modes"
amplitudes = [[1, 0.5]]

[[source]]
shape = "ball"
center = [0.0, 0.0, 1.0]
radius = 0.2
density = 2.0
)");
    const SceneSpec scene = loadScene(file);
    ASSERT_TRUE(scene.isSurface());
    EXPECT_TRUE(fs::equivalent(scene.surface->meshFile, mDir / "meshes" / "ball.obj"));
    EXPECT_TRUE(scene.domain.empty());
    EXPECT_EQ(scene.basis.velocityCount(), 12);
    EXPECT_EQ(scene.basis.scalarModes, 20);
    ASSERT_EQ(scene.sources.size(), 1u);
    EXPECT_EQ(scene.sources[0].shape.center, (Vec3{0.0, 0.0, 1.0}));
    EXPECT_FALSE(loadScene(write("grid.toml", std::string(kGrid2d) + kBasis)).isSurface());
}

TEST_F(SceneLoaderTest, SurfaceSceneRefusesTheGridsTablesAndKeys) {
    write("meshes/ball.obj", "v 0 0 0\n");
    const fs::path origin = mDir / "s.toml";
    const std::string surface = std::string(kSurface) + kBasis;
    EXPECT_CONTAINS(
        errorOf(std::string(kGrid3d) + surface, origin),
        "[grid]: a scene is either a grid scene ([grid], [[domain]]) or a surface scene "
        "([surface]), not both");
    EXPECT_CONTAINS(
        errorOf(surface + "[[domain]]\nshape = \"ball\"\ncenter = [0, 0, 0]\nradius = 1\n", origin),
        "[[domain]]: a scene is either a grid scene");
    EXPECT_CONTAINS(
        errorOf(surface + "[[obstacle]]\nshape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0, 0]]\n",
                origin),
        "[[obstacle]]: moving obstacles push on a grid's faces");
    EXPECT_CONTAINS(errorOf(surface + "[smoke]\nbuoyancy = 1.0\n", origin),
                    "[smoke]: buoyancy and the smoke grid");
    EXPECT_CONTAINS(
        errorOf(std::string(kSurface) + "[basis]\nvelocity_modes = 4\nwall = \"no-slip\"\n",
                origin),
        "[basis].wall: only for grid scenes");
    EXPECT_CONTAINS(errorOf(surface + "[simulation]\nmhd = true\n", origin),
                    "[simulation].mhd: MHD is simulated in grid scenes only");
    EXPECT_CONTAINS(errorOf(surface + "[initial]\nvelocity = \"vortices\"\n", origin),
                    "[initial].velocity: vortices are projected on a grid");
    EXPECT_CONTAINS(
        errorOf("[surface]\nmesh = \"meshes/ball.obj\"\nfile = \"x\"\n" + std::string(kBasis),
                origin),
        "[surface].file: unknown key");
    EXPECT_CONTAINS(errorOf("[surface]\nmesh = \"missing.obj\"\n" + std::string(kBasis), origin),
                    "[surface].mesh: no such file");
    EXPECT_CONTAINS(
        errorOf("[surface]\nmesh = \"meshes/ball.stl\"\n" + std::string(kBasis), origin),
        "[surface].mesh: only OBJ meshes are supported");
}

}  // namespace
}  // namespace modeflow
