/// @file SceneLoaderTest.cpp
/// Scene files → SceneSpec: every field round trips, defaults fill the gaps, and each kind of
/// mistake is refused with a message naming the file and the key (the table RefusedScene).

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/RuntimeLimits.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/SceneFixtures.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;
using testing::replaced;
using testing::sceneFixture;

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

// The base scenes of tests/data/scenes: 64² over ±1.1 and 16³ over ±1 (both with a blank line,
// [basis] and velocity_modes = 10 after the grid, so appended text starts on line 9), and 8 × 8
// cells over the unit square ([grid] on line 1).
const char* const k2d = "loader_2d";
const char* const k3d = "loader_3d";
const char* const kSquare = "loader_unit_square_2d";

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

// ---- refusals: one row per bad input ------------------------------------------------------------

/// A scene the loader refuses (read as scenes/bad.toml): a base fixture ("" for none) with
/// `replacements` made and `appended` added, and the fragments its message must contain; with
/// `atStart` the first fragment must begin the message.
struct Refusal {
    std::string name;
    std::string fixture;
    std::vector<std::pair<std::string, std::string>> replacements;
    std::string appended;
    std::vector<std::string> fragments;
    bool atStart = false;
};

std::ostream& operator<<(std::ostream& out, const Refusal& row) {
    return out << row.name;
}

class RefusedScene : public ::testing::TestWithParam<Refusal> {};

TEST_P(RefusedScene, WithAMessageNamingTheKey) {
    const Refusal& row = GetParam();
    const std::string base = row.fixture.empty() ? "" : sceneFixture(row.fixture);
    const std::string message = errorOf(replaced(base, row.replacements) + row.appended);
    for (const std::string& fragment : row.fragments) EXPECT_CONTAINS(message, fragment);
    if (row.atStart) {
        EXPECT_EQ(message.rfind(row.fragments.front(), 0), 0u) << message;
    }
}

const std::string kObstacleBall = "[[obstacle]]\nshape = \"ball\"\n";
const std::string kRandom = "[initial]\nvelocity = \"random\"\n";
const std::string kMhd = "[simulation]\nmhd = true\n[initial]\n";
const std::string kUniform = kMhd + "magnetic = \"uniform\"\n";
const std::string kForcing = "[forcing]\n";
const std::string kModes = "[initial]\nvelocity = \"modes\"\n";
const std::string kVortices = "[initial]\nvelocity = \"vortices\"\n";
const std::string kVortex = "[[initial.vortex]]\ncenter = [0, 0]\nstrength = 1\nradius = 0.1\n";
const std::string kVortices3d = kVortices + "energy = 0.7\n";
const std::string kRing =
    "[[initial.vortex]]\ncenter = [0, 0, 0]\nring_radius = 0.4\nradius = 0.1\nstrength = 3\n";
/// velocity_modes = 10 of the base fixtures, replaced by other [basis] keys.
std::pair<std::string, std::string> basis(const std::string& keys) {
    return {"velocity_modes = 10", keys};
}

/// `periodic = FLAGS` added to the unit square's [grid].
std::pair<std::string, std::string> periodicFlags(const std::string& flags) {
    return {"bounds_max = [1, 1]\n", "bounds_max = [1, 1]\nperiodic = " + flags + "\n"};
}

/// `open = SIDES` added to the unit square's [grid].
std::pair<std::string, std::string> openSides(const std::string& sides) {
    return {"bounds_max = [1, 1]\n", "bounds_max = [1, 1]\nopen = " + sides + "\n"};
}

const std::string kParticleBall =
    "[[particles]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\n";

// One row a line or two, as a table reads.
// clang-format off
const std::vector<Refusal> kRefusals = {
    // Particles.
    {"ParticlesWithoutCountOrRate", k2d, {}, kParticleBall,
     {"[[particles]] #1 (ball).count: missing: give count (particles at start) or rate"}},
    {"ParticlesWithCountAndRate", k2d, {}, kParticleBall + "count = 10\nrate = 5\n",
     {"[[particles]] #1 (ball).rate: give count (particles at start) or rate (per unit time), not both"}},
    {"ParticlesInATorus", k3d, {},
     "[[particles]]\nshape = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 0.5\nminor_radius = 0.1\ncount = 1\n",
     {"[[particles]] #1 (torus).shape: particles are seeded in a ball or a box"}},
    {"ParticlesAtAHugeRate", k2d, {}, kParticleBall + "rate = 1e12\n",
     {"[[particles]] #1 (ball).rate: the scene's sets would emit", "at most 16777216 fit"}},
    {"ParticlesTooManyInAll", k2d, {},
     kParticleBall + "count = 10000000\n" + kParticleBall + "count = 10000000\n",
     {"[[particles]] #2 (ball).count: the scene's sets would emit 2e+07"}},
    {"ParticlesCountZero", k2d, {}, kParticleBall + "count = 0\n", {"[[particles]] #1 (ball).count"}},
    {"ParticlesGravityOnTracers", k2d, {}, kParticleBall + "count = 5\ngravity = 1\n",
     {"[[particles]] #1 (ball).gravity: acts on inertial particles only (drag > 0)"}},
    {"ParticlesEndOfACount", k2d, {}, kParticleBall + "count = 5\nend = 1\n",
     {"[[particles]] #1 (ball).end: a set of count particles is seeded once"}},
    {"ParticlesEndBeforeStart", k2d, {}, kParticleBall + "rate = 5\nstart = 2\nend = 1\n",
     {"[[particles]] #1 (ball).end: must be later than start"}},
    {"ParticlesFallTooFast", k2d, {}, kParticleBall + "count = 5\ndrag = 1e-12\n",
     {"[[particles]] #1 (ball).gravity: falls at gravity / drag = 9.8e+12"}},
    {"ParticlesNegativeDrag", k2d, {}, kParticleBall + "count = 5\ndrag = -1\n",
     {"[[particles]] #1 (ball).drag"}},
    {"ParticlesMisspelledKey", k2d, {}, kParticleBall + "count = 5\ndarg = 1\n",
     {"[[particles]] #1 (ball).darg: unknown key (did you mean drag?)"}},
    {"ParticlesWithDensity", k2d, {}, kParticleBall + "count = 5\ndensity = 1\n",
     {"[[particles]] #1 (ball).density: unknown key"}},
    // Moving obstacles.
    {"ObstacleKeyFramesGoBack", k2d, {},
     kObstacleBall + "radius = 0.1\npath = [[1.0, 0.0, 0.0], [0.5, 0.1, 0.0]]\n",
     {"key frame times must increase"}},
    {"ObstacleKeyFrameWithoutTime", k2d, {}, kObstacleBall + "radius = 0.1\npath = [[1.0, 0.0]]\n",
     {"[t, position]"}},
    {"ObstacleBallWithoutRadius", k2d, {}, kObstacleBall + "path = [[0.0, 0.0, 0.0]]\n",
     {"radius"}},
    {"ObstacleBallWithHalfSize", k2d, {},
     kObstacleBall + "radius = 0.1\nhalf_size = [0.1, 0.1]\npath = [[0.0, 0.0, 0.0]]\n",
     {"half_size: not used by a ball"}},
    {"ObstacleCone", k2d, {}, "[[obstacle]]\nshape = \"cone\"\n", {"cone"}},
    {"SourceBallWithThickness", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\nthickness = 0.1\n",
     {"[[source]] #1 (ball).thickness: only a mesh source emits from a shell"}},
    {"ObstacleTooFast", k2d, {}, kObstacleBall + "radius = 0.1\npath = [[0, 0, 0], [1e-300, 1, 0]]\n",
     {"[[obstacle]] #1.path: moves faster than 1e+06 scene units per unit time"}},
    {"ObstacleTurnsTooFast", k2d, {},
     kObstacleBall + "radius = 0.1\npath = [[0, 0, 0]]\nrotation = [[0, 0, 0, 1, 0], [1, 0, 0, 1, 1e300]]\n",
     {"[[obstacle]] #1.rotation: turns faster than 1e+06 radians per unit time"}},
    {"SourceVelocityHuge", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\nvelocity = [1e300, 0]\n",
     {"[[source]] #1 (ball).velocity: speed 1e+300 is beyond 1e+06 scene units per unit time"}},
    {"SourceVelocityOfAnotherDimension", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\nvelocity = [1, 0, 0]\n",
     {"[[source]] #1 (ball).velocity"}},
    {"ObstacleMeshWithoutFile", k2d, {}, "[[obstacle]]\nshape = \"mesh\"\npath = [[0, 0, 0]]\n",
     {"[[obstacle]] #1.file: missing required key"}},
    {"ObstacleMeshOfNoFile", k2d, {},
     "[[obstacle]]\nshape = \"mesh\"\nfile = \"nothing.obj\"\npath = [[0, 0, 0]]\n",
     {"[[obstacle]] #1.file: no such file"}},
    {"ObstacleMeshWithRadius", k2d, {},
     "[[obstacle]]\nshape = \"mesh\"\nfile = \"a.obj\"\nradius = 1\npath = [[0, 0, 0]]\n",
     {"[[obstacle]] #1.radius: not used by a mesh"}},
    {"ObstacleBallWithScale", k2d, {}, kObstacleBall + "radius = 0.1\nscale = 2\npath = [[0, 0, 0]]\n",
     {"[[obstacle]] #1.scale: not used by a ball"}},
    {"FuelWithoutFire", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\nfuel = 1\n",
     {"[[source]] #1.fuel: fuel burns by a [fire] table"}},
    {"NegativeFuel", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\nfuel = -1\n",
     {"fuel", "-1"}},
    // Smoke values beyond 1e6 ran into float infinity on the device.
    {"SourceDensityHuge", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\ndensity = 1e300\n",
     {"[[source]] #1 (ball).density: 1e+300 is beyond 1e+06 in magnitude"}},
    {"SourceColdBeyondTheLimit", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\ntemperature = -2e6\n",
     {"[[source]] #1 (ball).temperature: -2e+06 is beyond 1e+06"}},
    {"WindBringingHugeSmoke", k2d, {}, "[wind]\nvelocity = [1, 0]\ndensity = 1e300\n",
     {"[wind].density: 1e+300 is beyond 1e+06"}},
    {"FireHeatHuge", k2d, {}, "[fire]\nheat = 1e7\n", {"[fire].heat: 1e+07 is beyond 1e+06"}},
    {"FireBurnRateZero", k2d, {}, "[fire]\nburn_rate = 0\n", {"[fire].burn_rate"}},
    {"FireHeatNaN", k2d, {}, "[fire]\nheat = nan\n", {"[fire].heat"}},
    {"FireUnknownKey", k2d, {}, "[fire]\nignite = 1\n", {"[fire]", "ignite", "ignition"}},
    // Wind.
    {"WindWithoutVelocity", k2d, {}, "[wind]\n", {"[wind].velocity: missing required key"}},
    {"WindOfAnotherDimension", k2d, {}, "[wind]\nvelocity = [1, 0, 0]\n", {"[wind].velocity"}},
    {"WindNaN", k2d, {}, "[wind]\nvelocity = [nan, 0]\n", {"[wind].velocity"}},
    {"WindHuge", k2d, {}, "[wind]\nvelocity = [1e300, 1e300]\n",
     {"[wind].velocity: speed 1.4e+300 is beyond 1e+06"}},
    {"WindUnknownKey", k2d, {}, "[wind]\nvelocity = [1, 0]\nprofil = 1\n",
     {"[wind]", "profil"}},
    {"BoundaryLayerAroundADomain", k2d, {},
     "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\n[wind]\nvelocity = [1, 0]\n"
     "profile = \"boundary-layer\"\nthickness = 0.2\n",
     {"[wind].profile: a boundary layer blows through a whole grid box", "[[obstacle]]"}},
    {"WindWithMhd", k2d, {}, "[simulation]\nmhd = true\n[wind]\nvelocity = [1, 0]\n",
     {"[wind]: a wind does not carry a magnetic field"}},
    {"WindMisspelledTable", k2d, {}, "[wnd]\nvelocity = [1, 0]\n", {"wnd", "did you mean wind?"}},
    {"WindBringingNegativeSmoke", k2d, {}, "[wind]\nvelocity = [1, 0]\ndensity = -0.5\n",
     {"[wind].density"}},
    {"WindBringingNaNHeat", k2d, {}, "[wind]\nvelocity = [1, 0]\ntemperature = nan\n",
     {"[wind].temperature"}},
    {"WindUnknownProfile", k2d, {}, "[wind]\nvelocity = [1, 0]\nprofile = \"log\"\n",
     {"[wind].profile", "boundary-layer"}},
    {"WindThicknessWithoutALayer", k2d, {}, "[wind]\nvelocity = [1, 0]\nthickness = 0.3\n",
     {"[wind].thickness: only a profile = \"boundary-layer\" has one"}},
    {"WindLayerWithoutThickness", k2d, {},
     "[wind]\nvelocity = [1, 0]\nprofile = \"boundary-layer\"\n",
     {"[wind].thickness: missing required key"}},
    {"WindLayerOfNegativeThickness", k2d, {},
     "[wind]\nvelocity = [1, 0]\nprofile = \"boundary-layer\"\nthickness = -0.2\n",
     {"[wind].thickness"}},
    {"WindLayerExponentAboveOne", k2d, {},
     "[wind]\nvelocity = [1, 0]\nprofile = \"boundary-layer\"\nthickness = 0.2\nexponent = 2\n",
     {"[wind].exponent: is 2; a boundary layer's power law has an exponent in (0, 1]"}},
    {"WindLayerBlowingUp", k2d, {},
     "[wind]\nvelocity = [1, 0.5]\nprofile = \"boundary-layer\"\nthickness = 0.2\n",
     {"[wind].velocity: a boundary layer's wind blows along the floor: its y (up) component "
      "must be 0"}},
    {"ObstacleBallWithSequenceRate", k2d, {},
     kObstacleBall + "radius = 0.1\nsequence_rate = 24\npath = [[0, 0, 0]]\n",
     {"[[obstacle]] #1.sequence_rate: not used by a ball"}},
    {"ObstacleMeshSequenceOfNoFirstFile", k2d, {},
     "[[obstacle]]\nshape = \"mesh\"\nfile = \"flag_####.obj\"\nsequence_rate = 24\npath = [[0, 0, 0]]\n",
     {"[[obstacle]] #1.file: no such file: ", "flag_0001.obj"}},
    {"RotationKeyFramesGoBack", k2d, {},
     kObstacleBall + "radius = 0.1\npath = [[0, 0, 0]]\nrotation = [[1, 0, 0, 1, 0], [0.5, 0, 0, 1, 9]]\n",
     {"[[obstacle]] #1.rotation", "key frame times must increase"}},
    {"RotationKeyFrameOfFourNumbers", k2d, {},
     kObstacleBall + "radius = 0.1\npath = [[0, 0, 0]]\nrotation = [[0, 0, 1, 90]]\n",
     {"[[obstacle]] #1.rotation", "[t, ax, ay, az, degrees]"}},
    {"RotationAboutNoAxis", k2d, {},
     kObstacleBall + "radius = 0.1\npath = [[0, 0, 0]]\nrotation = [[0, 0, 0, 0, 90]]\n",
     {"[[obstacle]] #1.rotation", "non-zero, finite length"}},
    {"RotationOutOfThePlane", k2d, {},
     kObstacleBall + "radius = 0.1\npath = [[0, 0, 0]]\nrotation = [[0, 1, 0, 0, 90]]\n",
     {"[[obstacle]] #1.rotation", "a 2D obstacle turns about z"}},
    {"RotationNotAnArray", k2d, {}, kObstacleBall + "radius = 0.1\npath = [[0, 0, 0]]\nrotation = 90\n",
     {"[[obstacle]] #1.rotation", "expected an array of key frames"}},
    // Unknown names, wrong types.
    {"BadModesString", k2d, {basis("modes = \"5-3\"")}, "",
     {"scenes/bad.toml: [basis].modes: "}, true},
    {"UnknownKey", k2d, {basis("velocity_mode = 10")}, "",
     {"scenes/bad.toml: [basis].velocity_mode: unknown key", "did you mean velocity_modes?"}, true},
    {"UnknownTable", k2d, {}, "[grdi]\nx = 1\n", {"grdi: unknown table", "did you mean grid?"}},
    {"ShapeKeyOfAnotherShape", k2d, {},
     "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\nradii = [1, 1]\n",
     {"[[domain]] #1 (ball).radii: not a key of a ball"}},
    {"UnknownOutputKey", k2d, {}, "[output]\nframes = 3\nfps = 24\n",
     {"[output].fps: unknown key"}},
    {"StringForNumber", k2d, {}, "[simulation]\ndt = \"fast\"\n",
     {"[simulation].dt: expected a number, got a string"}},
    // Floats where integers belong are errors, even when whole.
    {"FloatForInteger", k2d, {basis("velocity_modes = 40.0")}, "",
     {"[basis].velocity_modes: expected an integer, got a floating-point"}},
    {"FloatInResolution", kSquare, {{"[8, 8]", "[64, 64.5]"}}, "",
     {"[grid].resolution[1]: expected an integer"}},
    {"UnknownIntegrator", k2d, {}, "[simulation]\nintegrator = \"rk5\"\n",
     {"[simulation].integrator: unknown value \"rk5\"", "did you mean rk4?"}},
    {"UnknownEigensolver", k2d, {basis("velocity_modes = 4\neigensolver = \"arpack\"")}, "",
     {"[basis].eigensolver: unknown value \"arpack\"", "expected auto, spectra, block or slepc"}},
    // The grid.
    {"ResolutionBelowTwo", kSquare, {{"[8, 8]", "[64, 1]"}}, "",
     {"scenes/bad.toml: [grid].resolution[1]: must be between 2 and"}, true},
    {"FourResolutionEntries", kSquare, {{"[8, 8]", "[8, 8, 8, 8]"}}, "",
     {"scenes/bad.toml: [grid].resolution: expected 2 or 3 integers, got 4 entries"}, true},
    {"AbsurdlyLargeGrid", kSquare,
     {{"[8, 8]", "[4096, 4096, 4096]"}, {"[0, 0]", "[0, 0, 0]"}, {"[1, 1]", "[1, 1, 1]"}}, "",
     {"[grid].resolution", "absurdly large"}},
    {"TooWideGrid", kSquare, {{"[8, 8]", "[100000, 4]"}}, "", {"[grid].resolution[0]"}},
    {"InvertedBounds", kSquare, {{"[0, 0]", "[0, 1]"}, {"[1, 1]", "[1, -1]"}}, "",
     {"[grid].bounds_max", "inverted bounds", "axis y"}},
    // Extreme bounds passed the loader and failed deep inside the eigensolver ("penalty to nan").
    {"HugeCells", kSquare, {{"[0, 0]", "[-1e300, 0]"}, {"[1, 1]", "[1e300, 1]"}}, "",
     {"[grid].bounds_min/bounds_max: cells of 2.5e+299 along x are larger than 1e+06",
      "(line 4)"}},
    {"TinyCells", kSquare, {{"[1, 1]", "[1e-200, 1e-200]"}}, "",
     {"[grid].bounds_min/bounds_max: cells of 1.25e-201 along x are smaller than 1e-06"}},
    {"InfiniteExtent", kSquare, {{"[0, 0]", "[-1e308, 0]"}, {"[1, 1]", "[1e308, 1]"}}, "",
     {"[grid].bounds_min/bounds_max: bounds_max - bounds_min along x is not a finite number"}},
    {"StretchedCells", kSquare, {{"[1, 1]", "[8000, 4]"}}, "",
     {"[grid].bounds_min/bounds_max: cells are 2000 times longer along x (1000) than along y "
      "(0.5); at most 1000"}},
    {"FarFromTheOrigin", kSquare,
     {{"[0, 0]", "[1e15, 0]"}, {"[1, 1]", "[1.000000000000064e15, 64]"}},
     "",
     {"[grid].bounds_max: the grid lies 1.3e+14 cells (of 8) from the origin along x; at most "
      "1e+12"}},
    {"BoundsOfAnotherDimension", kSquare, {{"[0, 0]", "[0, 0, 0]"}}, "",
     {"[grid].bounds_min: expected 2 numbers"}},
    // Shapes.
    {"CylinderIn2d", k2d, {},
     "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\n"
     "[[domain]]\nshape = \"cylinder\"\ncenter = [0, 0]\nradius = 1\nhalf_height = 1\n",
     {"[[domain]] #2 (cylinder).shape", "3D only"}},
    {"TorusThickerThanWide", k3d, {},
     "[[domain]]\nshape = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 0.5\nminor_radius = 0.7\n",
     {"[[domain]] #1 (torus).minor_radius: must be less than major_radius"}},
    {"CentreOfAnotherDimension", k3d, {},
     "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.5\n",
     {"[[domain]] #1 (ball).center: expected 3 numbers"}},
    {"EmptyBox", k2d, {}, "[[domain]]\nshape = \"box\"\nmin = [0, 0]\nmax = [1, 0]\n",
     {"[[domain]] #1 (box).max: must exceed min"}},
    {"NegativeRadius", k2d, {}, "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = -1\n",
     {"[[domain]] #1 (ball).radius: must be > 0"}},
    {"MissingRadius", k2d, {}, "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\n",
     {"[[domain]] #1 (ball).radius: missing required key"}},
    {"TorusSource", k3d, {},
     "[[source]]\nshape = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 0.5\nminor_radius = 0.1\n",
     {"[[source]] #1 (torus).shape: a source must be a ball, a box or a mesh"}},
    {"MissingMesh", k3d, {}, "[[domain]]\nshape = \"mesh\"\nfile = \"missing.obj\"\n",
     {"[[domain]] #1 (mesh).file: no such file"}},
    {"FirstShapeSubtracted", k2d, {},
     "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 1\nop = \"subtract\"\n",
     {"[[domain]] #1 (ball).op"}},
    // Required tables and keys.
    {"BothVelocityModesAndModes", k2d, {basis("velocity_modes = 10\nmodes = \"1-10\"")}, "",
     {"[basis].modes", "velocity_modes", "not both"}},
    {"NoGrid", "", {}, "\n[basis]\nvelocity_modes = 10\n", {"[grid]: missing required table"}},
    {"NoBasis", k2d, {{"\n[basis]\nvelocity_modes = 10\n", ""}}, "",
     {"[basis]: missing required table"}},
    {"NoVelocityModes", k2d, {basis("scalar_modes = 3")}, "", {"[basis]: missing velocity_modes"}},
    {"NoBoundsMax", kSquare, {{"bounds_max = [1, 1]\n", ""}}, "",
     {"[grid].bounds_max: missing required key"}},
    {"NoVelocityMode", k2d, {basis("velocity_modes = 0")}, "",
     {"[basis].velocity_modes: must be at least 1"}},
    {"ModeBeyondTheGrid", k2d, {basis("velocity_modes = 100000")}, "",
     {"[basis].velocity_modes: mode 100000 is beyond the discrete space"}},
    {"DomainTable", k2d, {}, "[domain]\nshape = \"ball\"\n",
     {"[[domain]]: expected an array of tables"}},
    // Ranges.
    {"ZeroDt", k2d, {}, "[simulation]\ndt = 0\n", {"[simulation].dt: must be > 0"}},
    {"NegativeViscosity", k2d, {}, "[simulation]\nviscosity = -1\n",
     {"[simulation].viscosity: must be >= 0"}},
    {"NanDt", k2d, {}, "[simulation]\ndt = nan\n", {"[simulation].dt: must be finite"}},
    {"NegativeSeed", k2d, {}, kRandom + "seed = -1\n", {"[initial].seed: must be at least 0"}},
    {"SmokeScaleAboveEight", k2d, {}, "[smoke]\nresolution_scale = 9\n",
     {"[smoke].resolution_scale: must be between 1 and 8"}},
    {"UnknownAdvection", k2d, {}, "[smoke]\nadvection = \"bfecc\"\n", {"[smoke].advection"}},
    {"SourceEndsBeforeItStarts", k2d, {},
     "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\nstart = 2.0\nend = 1.0\n",
     {"end: must be later than start"}},
    {"UnknownPrecision", k2d, {}, "[simulation]\nbasis_precision = \"float8\"\n",
     {"[simulation].basis_precision"}},
    {"SubsamplesAbove16", k2d, {basis("velocity_modes = 4\nsubsamples = 17")}, "",
     {"[basis].subsamples: must be between 1 and 16"}},
    {"UnknownCoefficients", k2d, {basis("velocity_modes = 4\ncoefficients = \"packed\"")}, "",
     {"[basis].coefficients"}},
    {"NoFrames", k2d, {}, "[output]\nframes = 0\n", {"[output].frames: must be at least 1"}},
    {"HugeStepsPerFrame", k2d, {}, "[output]\nsteps_per_frame = 9999999999\n",
     {"[output].steps_per_frame: is too large"}},
    {"ErrorOnItsLine", k2d, {}, "[simulation]\n\ndt = -1\n", {"(line 11)"}},
    // Beyond a double's range TOML itself refuses the number, with its line.
    {"NumberBeyondADouble", k2d, {}, "[simulation]\ndt = 1e400\n", {"line 10, column"}},
    // Random initial velocity.
    {"NegativeEnergy", k2d, {}, kRandom + "energy = -1\n", {"[initial].energy: must be >= 0"}},
    {"BandFromZero", k2d, {}, kRandom + "band = [0, 4]\n",
     {"[initial].band: modes are numbered from 1"}},
    {"BackwardBand", k2d, {}, kRandom + "band = [5, 4]\n",
     {"[initial].band: ends before it starts"}},
    {"BandBeyondTheBasis", k2d, {}, kRandom + "band = [1, 11]\n",
     {"[initial].band: mode 11 is beyond the basis ([basis] has 10"}},
    {"BandNotAPair", k2d, {}, kRandom + "band = 3\n", {"[initial].band: expected [first, last]"}},
    {"FloatInBand", k2d, {}, kRandom + "band = [1, 2.5]\n",
     {"[initial].band[1]: expected an integer"}},
    {"MisspeltBand", k2d, {}, kRandom + "bnad = [1, 2]\n",
     {"[initial].bnad: unknown key (did you mean band?)"}},
    {"AmplitudesWithRandom", k2d, {}, kRandom + "amplitudes = [[1, 1.0]]\n",
     {"[initial].amplitudes: not used with velocity = \"random\" (it takes energy, seed and "
      "band)"}},
    // Initial speeds beyond what a step can take: energy = 1e300 was accepted and later blamed on
    // dt ("energy = inf").
    {"AbsurdEnergy", k2d, {}, kRandom + "energy = 1e300\n",
     {"[initial].energy: 1e+300 is a mean speed of 6.4e+149 (sqrt(2 energy / grid volume 4.8)); "
      "at most 1e+06 scene units per unit time (line 11)"}},
    {"AbsurdAmplitude", k2d, {}, kModes + "amplitudes = [[1, 1], [2, 1e200]]\n",
     {"[initial].amplitudes: ½Σa² = inf is a mean speed of inf"}},
    {"AbsurdMagneticEnergy", k2d, {}, kMhd + "magnetic_energy = 1e300\n",
     {"[initial].magnetic_energy: 1e+300 is a mean field of 6.4e+149"}},
    {"AbsurdMagneticStrength", k2d, {},
     kUniform + "magnetic_direction = [1, 0]\nmagnetic_strength = 2e6\n",
     {"[initial].magnetic_strength: 2e+06 is beyond 1e+06"}},
    {"AbsurdVortexStrength", k2d, {},
     kVortices + "[[initial.vortex]]\ncenter = [0, 0]\nstrength = 1e300\nradius = 0.1\n",
     {"[[initial.vortex]] #1.strength: magnitude 1e+300 is beyond 2.2e+06 (1e+06 scene units per "
      "unit time times the grid's longest side, 2.2)"}},
    // Magnetic fields.
    {"MisspeltMagnetic", k2d, {}, kMhd + "magnetic = \"uniforn\"\n",
     {"[initial].magnetic: unknown value \"uniforn\" (did you mean uniform?)"}},
    {"UniformWithoutDirection", k2d, {}, kUniform,
     {"[initial].magnetic_direction: missing required key"}},
    {"DirectionOfAnotherDimension", k2d, {}, kUniform + "magnetic_direction = [1, 0, 0]\n",
     {"[initial].magnetic_direction: expected 2 numbers (the scene is 2D)"}},
    {"ZeroDirection", k2d, {}, kUniform + "magnetic_direction = [0, 0]\n",
     {"[initial].magnetic_direction: must be a non-zero vector"}},
    {"NegativeStrength", k2d, {},
     kUniform + "magnetic_direction = [1, 0]\nmagnetic_strength = -1\n",
     {"[initial].magnetic_strength: must be >= 0"}},
    {"EnergyWithUniform", k2d, {}, kUniform + "magnetic_direction = [1, 0]\nmagnetic_energy = 1\n",
     {"[initial].magnetic_energy: not used with magnetic = \"uniform\" (it takes "
      "magnetic_direction, magnetic_strength and magnetic_wall_layer)"}},
    {"ZeroWallLayer", k2d, {},
     kUniform + "magnetic_direction = [1, 0]\nmagnetic_wall_layer = 0\n",
     {"[initial].magnetic_wall_layer: must be > 0"}},
    {"StrengthWithRandom", k2d, {}, kMhd + "magnetic_strength = 1\n",
     {"[initial].magnetic_strength: not used with magnetic = \"random\""}},
    {"MisspeltDirection", k2d, {}, kMhd + "magnetic_directoin = [1, 0]\n",
     {"[initial].magnetic_directoin: unknown key (did you mean magnetic_direction?)"}},
    {"MagneticWithoutMhd", k2d, {}, "[initial]\nmagnetic = \"uniform\"\n",
     {"[initial].magnetic: only used with [simulation] mhd = true"}},
    // Forcing.
    {"ForcingHoldsNothing", k2d, {}, kForcing,
     {"[forcing]: missing hold_modes (e.g. \"1-5\") or hold_below_kappa (e.g. 2.0)"}},
    {"ForcingHoldsBoth", k2d, {}, kForcing + "hold_modes = \"1\"\nhold_below_kappa = 2.0\n",
     {"[forcing].hold_below_kappa: give either hold_modes or hold_below_kappa, not both"}},
    {"ForcingBelowZeroKappa", k2d, {}, kForcing + "hold_below_kappa = 0\n",
     {"[forcing].hold_below_kappa: must be > 0"}},
    {"ForcingBackwardModes", k2d, {}, kForcing + "hold_modes = \"3-1\"\n",
     {"[forcing].hold_modes: bad mode list"}},
    {"ForcingBeyondTheBasis", k2d, {}, kForcing + "hold_modes = \"9-11\"\n",
     {"[forcing].hold_modes: mode 11 is beyond the basis ([basis] has 10 velocity modes)"}},
    {"ForcingUnknownKey", k2d, {}, kForcing + "hold = 2\n", {"[forcing].hold: unknown key"}},
    {"ForcingWithMhd", k2d, {}, "[simulation]\nmhd = true\n[forcing]\nhold_modes = \"1\"\n",
     {"[forcing]: holds velocity modes of the fluid model; it cannot be combined with "
      "[simulation] mhd"}},
    {"MisspeltForcing", k2d, {}, "[forcng]\n", {"unknown table (did you mean forcing?)"}},
    {"LinearizedMhd", k2d, {}, "[simulation]\nintegrator = \"linearized\"\nmhd = true\n",
     {"[simulation].integrator: linearized is for fluids; MHD takes midpoint (or trapezoidal, "
      "explicit, rk4)"}},
    // Modal amplitudes.
    {"ModesWithoutAmplitudes", k2d, {}, kModes,
     {"[initial].amplitudes: missing required key for velocity = \"modes\""}},
    {"NoAmplitudes", k2d, {}, kModes + "amplitudes = []\n",
     {"[initial].amplitudes: expected a non-empty array"}},
    {"AmplitudeNotAPair", k2d, {}, kModes + "amplitudes = [1, 0.5]\n",
     {"[initial].amplitudes[0]: expected a [mode, amplitude] pair, got an integer"}},
    {"AmplitudeTriple", k2d, {}, kModes + "amplitudes = [[1, 0.5, 2]]\n",
     {"[initial].amplitudes[0]: expected a [mode, amplitude] pair, got 3 entries"}},
    {"AmplitudeOfModeZero", k2d, {}, kModes + "amplitudes = [[0, 0.5]]\n",
     {"[initial].amplitudes[0]: mode 0 is outside the basis (modes 1 to 10)"}},
    {"AmplitudeBeyondTheBasis", k2d, {}, kModes + "amplitudes = [[2, 1], [11, 0.5]]\n",
     {"[initial].amplitudes[1]: mode 11 is outside the basis"}},
    {"AmplitudeTwice", k2d, {}, kModes + "amplitudes = [[2, 1], [2, 0.5]]\n",
     {"[initial].amplitudes[1]: mode 2 is given twice"}},
    {"FloatModeNumber", k2d, {}, kModes + "amplitudes = [[1.5, 1]]\n",
     {"[initial].amplitudes[0][0]: expected an integer"}},
    {"StringAmplitude", k2d, {}, kModes + "amplitudes = [[1, \"big\"]]\n",
     {"[initial].amplitudes[0][1]: expected a number, got a string"}},
    {"SeedWithModes", k2d, {}, kModes + "amplitudes = [[1, 1]]\nseed = 3\n",
     {"[initial].seed: not used with velocity = \"modes\" (it takes amplitudes)"}},
    {"EnergyOfZeroVelocity", k2d, {}, "[initial]\nenergy = 1\n",
     {"[initial].energy: not used with velocity = \"zero\" (it takes no other key)"}},
    // Vortices.
    {"NoVortex", k2d, {}, kVortices, {"[[initial.vortex]]: missing"}},
    {"VortexNotATable", k2d, {}, kVortices + "vortex = 3\n",
     {"[[initial.vortex]]: expected an array of tables"}},
    {"SeedWithVortices", k2d, {}, kVortices + "energy = 2\nseed = 1\n" + kVortex,
     {"[initial].seed: not used with velocity = \"vortices\" (it takes vortex and energy)"}},
    {"VortexWithoutStrength", k2d, {},
     kVortices + "[[initial.vortex]]\ncenter = [0, 0]\nradius = 0.1\n",
     {"[[initial.vortex]] #1.strength: missing required key"}},
    {"ZeroVortexRadius", k2d, {},
     kVortices + kVortex + "[[initial.vortex]]\ncenter = [0, 0]\nstrength = 1\nradius = 0\n",
     {"[[initial.vortex]] #2.radius: must be > 0"}},
    {"VortexCentreOfAnotherDimension", k2d, {},
     kVortices + "[[initial.vortex]]\ncenter = [0, 0, 0]\nstrength = 1\nradius = 0.1\n",
     {"[[initial.vortex]] #1.center: expected 2 numbers (the scene is 2D)"}},
    {"MisspeltStrength", k2d, {}, kVortices + kVortex + "strenght = 2\n",
     {"[[initial.vortex]] #1.strenght: unknown key (did you mean strength?)"}},
    {"RingRadiusIn2d", k2d, {}, kVortices + kVortex + "ring_radius = 0.5\n",
     {"[[initial.vortex]] #1.ring_radius: only 3D vortex rings take it"}},
    {"StringStrength", k2d, {},
     kVortices + "[[initial.vortex]]\ncenter = [0, 0]\nstrength = \"big\"\nradius = 0.1\n",
     {"[[initial.vortex]] #1.strength: expected a number, got a string"}},
    {"RingWithoutNormal", k3d, {}, kVortices3d + kRing,
     {"[[initial.vortex]] #1.normal: missing required key"}},
    {"ZeroNormal", k3d, {}, kVortices3d + kRing + "normal = [0, 0, 0]\n",
     {"[[initial.vortex]] #1.normal: must be a non-zero vector"}},
    {"RingWithoutRingRadius", k3d, {},
     kVortices3d +
         "[[initial.vortex]]\ncenter = [0, 0, 0]\nnormal = [0, 0, 1]\nradius = 0.1\nstrength = 3\n",
     {"[[initial.vortex]] #1.ring_radius: missing required key"}},
    // Hostile values: integers beyond their range.
    {"HugeResolution", kSquare, {{"[8, 8]", "[9223372036854775807, 8]"}}, "",
     {"[grid].resolution[0]: must be between 2 and 4096, got 9223372036854775807"}},
    // TOML refuses it: not representable in 64 bits.
    {"ResolutionBeyond64Bits", "", {}, "[grid]\nresolution = [9223372036854775808, 8]\n",
     {"line 2, column"}},
    {"ModeBeyondTheDiscreteSpace", k2d, {basis("modes = \"1-2147483647\"")}, "",
     {"[basis].modes: mode 2147483647 is beyond the discrete space"}},
    {"ModeBeyondAnInt", k2d, {basis("modes = \"1-2147483648\"")}, "",
     {"[basis].modes: bad mode list \"1-2147483648\": mode number at position 3 is too large"}},
    {"BandBeyondAnInt", k2d, {}, kRandom + "band = [1, 4294967297]\n",
     {"[initial].band: mode 4294967297 is beyond the basis"}},
    {"NegativeMagneticSeed", k2d, {}, kMhd + "magnetic_seed = -3\n",
     {"[initial].magnetic_seed: must be at least 0, got -3"}},
    // frames x steps_per_frame is the step count, an int.
    {"StepCountBeyondAnInt", k2d, {}, "[output]\nframes = 100000\nsteps_per_frame = 100000\n",
     {"[output].steps_per_frame: frames x steps_per_frame = 10000000000 steps, more than "
      "2147483647"}},
    // Negative zero is not a size.
    {"NegativeZeroRadius", k2d, {},
     "[[domain]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = -0.0\n",
     {"[[domain]] #1 (ball).radius: must be > 0, got -0"}},
    {"NegativeZeroWidth", kSquare, {{"[0, 0]", "[-0.0, 0]"}, {"[1, 1]", "[0.0, 1]"}}, "",
     {"[grid].bounds_max: must exceed bounds_min on every axis"}},
    // An empty file, and arrays of tables where tables belong.
    {"EmptyFile", "", {}, "", {"scenes/bad.toml: [grid]: missing required table"}},
    {"GridArray", "", {}, "[[grid]]\nresolution = [8, 8]\n",
     {"[grid]: expected a table, got an array (line 1)"}},
    {"BasisArray", k2d, {{"\n[basis]\nvelocity_modes = 10\n", ""}},
     "[[basis]]\nvelocity_modes = 4\n",
     {"[basis]: expected a table, got an array"}},
    {"InitialArray", k2d, {}, "[[initial]]\nvelocity = \"zero\"\n",
     {"[initial]: expected a table, got an array"}},
    {"VortexTable", k2d, {}, kVortices + "[initial.vortex]\ncenter = [0, 0]\n",
     {"[[initial.vortex]]: expected an array of tables"}},
    // Periodic axes.
    {"OnePeriodicFlag", kSquare, {periodicFlags("[true]"), basis("velocity_modes = 4")}, "",
     {"[grid].periodic: expected 2 booleans"}},
    {"ThreePeriodicFlags", kSquare,
     {periodicFlags("[true, false, true]"), basis("velocity_modes = 4")}, "",
     {"expected 2 booleans"}},
    {"PeriodicNotAnArray", kSquare, {periodicFlags("true"), basis("velocity_modes = 4")}, "",
     {"expected 2 booleans"}},
    {"PeriodicNumbers", kSquare, {periodicFlags("[1, 0]"), basis("velocity_modes = 4")}, "",
     {"[grid].periodic[0]: expected true or false"}},
    // Open sides.
    {"OpenNotAnArray", kSquare, {openSides("\"y_max\""), basis("velocity_modes = 4")}, "",
     {"[grid].open: expected an array of side names (\"x_min\" ... \"y_max\"), got a string"}},
    {"OpenUnknownSide", kSquare, {openSides("[\"top\"]"), basis("velocity_modes = 4")}, "",
     {"[grid].open[0]: expected a side of the 2D box: x_min, x_max, y_min or y_max, got \"top\""}},
    {"OpenZSideIn2D", kSquare, {openSides("[\"y_max\", \"z_max\"]"), basis("velocity_modes = 4")},
     "", {"[grid].open[1]: expected a side of the 2D box"}},
    {"OpenNotAString", kSquare, {openSides("[1]"), basis("velocity_modes = 4")}, "",
     {"[grid].open[0]: expected a side of the 2D box: x_min, x_max, y_min or y_max, got an integer"}},
    {"OpenTwice", kSquare, {openSides("[\"y_max\", \"y_max\"]"), basis("velocity_modes = 4")},
     "", {"[grid].open[1]: \"y_max\" is listed twice"}},
    {"OpenAcrossAPeriodicAxis", kSquare,
     {{"bounds_max = [1, 1]\n", "bounds_max = [1, 1]\nperiodic = [true, false]\n"
                               "open = [\"x_min\"]\n"},
      basis("velocity_modes = 4")},
     "", {"[grid].open[0]: \"x_min\" lies across a periodic axis"}},
    {"OpenAlongTheWind", kSquare, {openSides("[\"y_max\", \"x_min\"]"), basis("velocity_modes = 4")},
     "[wind]\nvelocity = [1, 0]\n",
     {"[wind].velocity: the wind blows along x, whose sides it opens itself: leave x_min and "
      "x_max out of [grid].open"}},
    {"BoundaryLayerOverAnOpenFloor", kSquare,
     {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[wind]\nvelocity = [1, 0]\nprofile = \"boundary-layer\"\nthickness = 0.2\n",
     {"[wind].profile: a boundary layer grows over the floor, and this scene's y_min is open"}},
    // Inflows: through a side the air crosses, where their shape meets it.
    {"InflowWithoutASide", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\ncenter = [0.5, 0]\nradius = 0.2\n",
     {"[[inflow]] #1 (ball).side: missing required key (x_min, x_max, y_min or y_max)"}},
    {"InflowOnAnUnknownSide", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"floor\"\ncenter = [0.5, 0]\nradius = 0.2\n",
     {"[[inflow]] #1 (ball).side: expected a side of the 2D box: x_min, x_max, y_min or y_max, "
      "got \"floor\""}},
    {"InflowThroughAWall", kSquare, {openSides("[\"y_max\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.2\n",
     {"[[inflow]] #1 (ball).side: y_min is a wall: open it ([grid] open = [\"y_min\"]) or let a "
      "[wind] blow in through it"}},
    {"InflowWhereTheWindLeaves", kSquare, {basis("velocity_modes = 4")},
     "[wind]\nvelocity = [1, 0]\n[[inflow]]\nshape = \"ball\"\nside = \"x_max\"\n"
     "center = [1, 0.5]\nradius = 0.2\n",
     {"[[inflow]] #1 (ball).side: the wind leaves the box through x_max; it comes in through "
      "x_min"}},
    {"InflowAcrossAPeriodicAxis", kSquare,
     {{"bounds_max = [1, 1]\n", "bounds_max = [1, 1]\nperiodic = [true, false]\n"
                                "open = [\"y_min\"]\n"},
      basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"x_min\"\ncenter = [0, 0.5]\nradius = 0.2\n",
     {"[[inflow]] #1 (ball).side: \"x_min\" lies across a periodic axis"}},
    {"InflowAwayFromItsSide", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"box\"\nside = \"y_min\"\nmin = [0.4, 0.1]\nmax = [0.6, 0.2]\n",
     {"[[inflow]] #1 (box).min: the box does not reach across the plane of y_min"}},
    {"InflowCoveringNoFace", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.01\n",
     {"[[inflow]] #1 (ball).radius: where the ball meets y_min it holds the centre of no smoke "
      "cell's face there: make it larger"}},
    {"InflowBoxBetweenFaces", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"box\"\nside = \"y_min\"\nmin = [0.51, -0.1]\nmax = [0.55, 0.1]\n",
     {"[[inflow]] #1 (box).max: where the box meets y_min it holds the centre of no smoke cell's "
      "face there"}},
    {"InflowOfAMesh", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"mesh\"\nside = \"y_min\"\n",
     {"[[inflow]] #1 (mesh).shape: an inflow is a ball or a box, got mesh"}},
    {"InflowOfFuelWithoutAFire", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.2\n"
     "fuel = 1\n",
     {"[[inflow]] #1 (ball).fuel: fuel burns by a [fire] table"}},
    {"InflowOfNegativeDensity", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.2\n"
     "density = -1\n",
     {"[[inflow]] #1 (ball).density"}},
    {"InflowEndingBeforeItStarts", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.2\n"
     "start = 1\nend = 0.5\n",
     {"[[inflow]] #1 (ball).end: must be later than start (1)"}},
    {"InflowTooFast", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.2\n"
     "velocity = [0, 1e300]\n",
     {"[[inflow]] #1 (ball).velocity: speed 1e+300 is beyond"}},
    {"InflowWithAnUnknownKey", kSquare, {openSides("[\"y_min\"]"), basis("velocity_modes = 4")},
     "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = 0.2\n"
     "speed = 2\n",
     {"[[inflow]] #1 (ball).speed"}},
    // A 4 × 4 torus has 32 faces (a walled 4 × 4 box 40): mode 36 lies beyond it.
    {"ModeBeyondTheFacesOfATorus", kSquare,
     {{"[8, 8]", "[4, 4]"}, periodicFlags("[true, true]"),
      basis("velocity_modes = 36\nscalar_modes = 0")},
     "", {"the grid has only 32 faces"}},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(SceneLoader, RefusedScene, ::testing::ValuesIn(kRefusals),
                         [](const ::testing::TestParamInfo<Refusal>& info) {
                             return info.param.name;
                         });

// ---- what is read ------------------------------------------------------------------------------

TEST_F(SceneLoaderTest, FullSceneRoundTripsEveryField) {
    write("meshes/bunny.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const fs::path file = write("full_scene.toml", sceneFixture("loader_full_3d"));
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

TEST_F(SceneLoaderTest, AWindBlowsThroughTheWholeBox) {
    const SceneSpec scene =
        parseScene(sceneFixture(k2d) + "[wind]\nvelocity = [1.5, -0.25]\n", "wind.toml");
    ASSERT_TRUE(scene.wind.has_value());
    EXPECT_EQ(scene.wind->velocity, (Vec3{1.5, -0.25, 0.0}));
    EXPECT_FALSE(parseScene(sceneFixture(k2d), "still.toml").wind.has_value());
    const SceneSpec three =
        parseScene(sceneFixture(k3d) + "[wind]\nvelocity = [0, 0, 2]\n", "wind.toml");
    ASSERT_TRUE(three.wind.has_value());
    EXPECT_EQ(three.wind->velocity, (Vec3{0.0, 0.0, 2.0}));
    EXPECT_EQ(three.wind->profile, WindProfile::Uniform);
    EXPECT_EQ(three.wind->density, 0.0) << "clean air by default";
    EXPECT_EQ(three.wind->temperature, 0.0);
    const SceneSpec hazy = parseScene(
        sceneFixture(k2d) + "[wind]\nvelocity = [1, 0]\ndensity = 0.2\ntemperature = -1.5\n",
        "hazy.toml");
    EXPECT_EQ(hazy.wind->density, 0.2);
    EXPECT_EQ(hazy.wind->temperature, -1.5);
    const SceneSpec layer = parseScene(sceneFixture(k3d) + R"([wind]
velocity = [1, 0.5, 0]
profile = "boundary-layer"
thickness = 0.3
)",
                                       "layer.toml");
    ASSERT_TRUE(layer.wind.has_value());
    EXPECT_EQ(layer.wind->profile, WindProfile::BoundaryLayer);
    EXPECT_EQ(layer.wind->thickness, 0.3);
    EXPECT_EQ(layer.wind->exponent, 1.0 / 7.0);
    const SceneSpec linear = parseScene(sceneFixture(k2d) +
                                            "[wind]\nvelocity = [1, 0]\nprofile = "
                                            "\"boundary-layer\"\nthickness = 0.5\nexponent = 1\n",
                                        "linear.toml");
    EXPECT_EQ(linear.wind->exponent, 1.0);
}

TEST_F(SceneLoaderTest, InflowsLetAirInThroughOpenSidesAndTheWindsUpstreamOne) {
    const std::string open = replaced(sceneFixture(kSquare), "bounds_max = [1, 1]\n",
                                      "bounds_max = [1, 1]\nopen = [\"y_min\", \"y_max\"]\n");
    const SceneSpec scene = parseScene(open + R"([[inflow]]
shape = "box"
side = "y_min"
min = [0.4, -0.1]
max = [0.6, 0.05]
velocity = [0, 2]
density = 1
temperature = 0.5
start = 0.25
end = 2
[[inflow]]
shape = "ball"
side = "y_max"
center = [0.2, 1]
radius = 0.1
)",
                                       "inflow.toml");
    ASSERT_EQ(scene.inflows.size(), 2u);
    const InflowSpec& jet = scene.inflows[0];
    EXPECT_EQ(jet.side, 2);
    EXPECT_EQ(jet.shape.kind, ShapeKind::Box);
    EXPECT_EQ(jet.shape.min, (Vec3{0.4, -0.1, 0.0}));
    ASSERT_TRUE(jet.velocity.has_value());
    EXPECT_EQ(*jet.velocity, (Vec3{0.0, 2.0, 0.0}));
    EXPECT_EQ(jet.density, 1.0);
    EXPECT_EQ(jet.temperature, 0.5);
    EXPECT_EQ(jet.start, 0.25);
    EXPECT_EQ(jet.end, 2.0);
    const InflowSpec& vent = scene.inflows[1];
    EXPECT_EQ(vent.side, 3);
    EXPECT_FALSE(vent.velocity.has_value());
    EXPECT_EQ(vent.density, 0.0) << "clean air by default";
    EXPECT_EQ(vent.fuel, 0.0);
    EXPECT_EQ(vent.end, std::numeric_limits<double>::infinity());
    // Upstream of a wind, with no side open; fuel with a fire.
    const SceneSpec rake = parseScene(sceneFixture(kSquare) + R"([wind]
velocity = [-1, 0]
[fire]
[[inflow]]
shape = "ball"
side = "x_max"
center = [1, 0.5]
radius = 0.1
density = 2
fuel = 1
)",
                                      "rake.toml");
    ASSERT_EQ(rake.inflows.size(), 1u);
    EXPECT_EQ(rake.inflows[0].side, 1);
    EXPECT_EQ(rake.inflows[0].fuel, 1.0);
    // No more than the runtime takes.
    std::string many = open;
    for (int i = 0; i <= maxInflows; ++i)
        many +=
            "[[inflow]]\nshape = \"ball\"\nside = \"y_min\"\ncenter = [0.5, 0]\nradius = "
            "0.1\n";
    EXPECT_CONTAINS(errorOf(many), "[[inflow]]: 17 entries; at most 16 inflows take part");
}

TEST_F(SceneLoaderTest, AFireBurnsTheFuelOfItsSources) {
    const std::string source = R"(
[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.1
temperature = 2
fuel = 3
)";
    const SceneSpec scene = parseScene(sceneFixture(k2d) + source + R"(
[fire]
ignition = 0.5
burn_rate = 6
heat = 1.5
smoke = 0.2
)",
                                       "fire.toml");
    ASSERT_EQ(scene.sources.size(), 1u);
    EXPECT_EQ(scene.sources[0].fuel, 3.0);
    ASSERT_TRUE(scene.fire.has_value());
    EXPECT_EQ(scene.fire->ignition, 0.5);
    EXPECT_EQ(scene.fire->burnRate, 6.0);
    EXPECT_EQ(scene.fire->heat, 1.5);
    EXPECT_EQ(scene.fire->smoke, 0.2);
    // Every key has a default; without [fire] there is none (and no fuel may be given).
    const SceneSpec defaults = parseScene(sceneFixture(k2d) + "[fire]\n", "fire.toml");
    ASSERT_TRUE(defaults.fire.has_value());
    EXPECT_EQ(defaults.fire->burnRate, FireSpec{}.burnRate);
    EXPECT_FALSE(parseScene(sceneFixture(k2d), "plain.toml").fire.has_value());
}

TEST_F(SceneLoaderTest, ObstaclesFollowKeyFramedPaths) {
    const SceneSpec scene = parseScene(sceneFixture(k2d) + R"(
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
    EXPECT_TRUE(scene.obstacles[0].rotation.empty()) << "without rotation keys it never turns";
}

TEST_F(SceneLoaderTest, ObstaclesTurnAlongRotationKeyFrames) {
    const SceneSpec scene = parseScene(sceneFixture(k2d) + R"(
[[obstacle]]
shape = "box"
half_size = [0.3, 0.05]
path = [[0.0, 0.0, 0.0]]
rotation = [[0.0, 0, 0, 2, 0], [1.0, 0, 0, -1, 720]]
)",
                                       "turning.toml");
    ASSERT_EQ(scene.obstacles.size(), 1u);
    const std::vector<RotationKey>& keys = scene.obstacles[0].rotation;
    ASSERT_EQ(keys.size(), 2u);
    EXPECT_EQ(keys[0].time, 0.0);
    EXPECT_EQ(keys[0].axis, (Vec3{0.0, 0.0, 1.0})) << "axes are normalized";
    EXPECT_EQ(keys[1].axis, (Vec3{0.0, 0.0, -1.0}));
    EXPECT_EQ(keys[1].degrees, 720.0);
}

TEST_F(SceneLoaderTest, ParticleSetsReadTheirKeys) {
    const SceneSpec scene = parseScene(sceneFixture(k2d) + R"(
[[particles]]
shape = "ball"
center = [0.1, -0.2]
radius = 0.3
count = 500

[[particles]]
shape = "box"
min = [-0.5, -1.0]
max = [0.5, -0.9]
rate = 2000
start = 0.25
end = 0.75
drag = 4
gravity = 2
seed = 9
)",
                                       "leaves.toml");
    ASSERT_EQ(scene.particles.size(), 2u);
    const ParticleSetSpec& tracers = scene.particles[0];
    EXPECT_EQ(tracers.region.kind, ShapeKind::Ball);
    EXPECT_EQ(tracers.region.center, (Vec3{0.1, -0.2, 0.0}));
    EXPECT_EQ(tracers.count, 500);
    EXPECT_EQ(tracers.rate, 0.0);
    EXPECT_EQ(tracers.drag, 0.0);
    EXPECT_EQ(tracers.seed, 1u);
    const ParticleSetSpec& leaves = scene.particles[1];
    EXPECT_EQ(leaves.region.kind, ShapeKind::Box);
    EXPECT_EQ(leaves.region.max, (Vec3{0.5, -0.9, 0.0}));
    EXPECT_EQ(leaves.rate, 2000.0);
    EXPECT_EQ(leaves.start, 0.25);
    EXPECT_EQ(leaves.end, 0.75);
    EXPECT_EQ(leaves.drag, 4.0);
    EXPECT_EQ(leaves.gravity, 2.0);
    EXPECT_EQ(leaves.seed, 9u);
    // A rate past the shot's end (48 frames of 0.02) counts only what the shot emits.
    EXPECT_NO_THROW(parseScene(sceneFixture(k2d) + kParticleBall + "rate = 16000000\n", "x.toml"));
}

TEST_F(SceneLoaderTest, MinimalSceneGetsDefaults) {
    const SceneSpec scene = parseScene(sceneFixture(k2d), "somewhere/minimal.toml");
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
    const SceneSpec scene = parseScene(sceneFixture(k2d) + R"(
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

TEST_F(SceneLoaderTest, ExtremeBoundsAtTheLimitsAreAccepted) {
    // The limits the HugeCells, TinyCells and StretchedCells refusals name, in 3D too.
    const std::string square = sceneFixture(kSquare);
    EXPECT_EQ(errorOf(replaced(square, "[1, 1]", "[8e-6, 8e-3]")), "");
    EXPECT_EQ(errorOf(replaced(square, {{"[0, 0]", "[-4e6, 0]"}, {"[1, 1]", "[4e6, 8e3]"}})), "");
    EXPECT_EQ(errorOf(replaced(square, {{"[8, 8]", "[8, 8, 8]"},
                                        {"[0, 0]", "[0, 0, 0]"},
                                        {"[1, 1]", "[8e-6, 8e-3, 8e-4]"}})),
              "");
}

TEST_F(SceneLoaderTest, MeshPathThatIsNotAFileSaysWhatItIs) {
    fs::create_directories(mDir / "folder.obj");
    ASSERT_EQ(::mkfifo((mDir / "pipe.obj").c_str(), 0600), 0);
    const auto meshScene = [](const std::string& file) {
        return sceneFixture(k3d) + "[[domain]]\nshape = \"mesh\"\nfile = \"" + file + "\"\n";
    };
    std::string message = errorOf(meshScene("folder.obj"), mDir / "s.toml");
    EXPECT_CONTAINS(message, "[[domain]] #1 (mesh).file: " + (mDir / "folder.obj").string() +
                                 " is a directory, not an OBJ file");
    message = errorOf(meshScene("pipe.obj"), mDir / "s.toml");
    EXPECT_CONTAINS(message, "pipe.obj is a FIFO, not an OBJ file");
    message = errorOf(meshScene("missing.obj"), mDir / "s.toml");
    EXPECT_CONTAINS(message, "[[domain]] #1 (mesh).file: no such file: ");
}
TEST_F(SceneLoaderTest, AMeshSequenceNeedsItsRateAndARateItsSequence) {
    write("flag_0001.obj", "v 0 0 0\n");
    write("plate.obj", "v 0 0 0\n");
    const auto obstacle = [](const std::string& keys) {
        return sceneFixture(k3d) + "[[obstacle]]\nshape = \"mesh\"\npath = [[0, 0, 0, 0]]\n" + keys;
    };
    const SceneSpec scene =
        loadScene(write("s.toml", obstacle("file = \"flag_####.obj\"\nsequence_rate = 24\n")));
    EXPECT_EQ(scene.obstacles[0].sequenceRate, 24.0);
    EXPECT_EQ(scene.obstacles[0].meshFile.filename(), "flag_####.obj");
    EXPECT_CONTAINS(errorOf(obstacle("file = \"flag_####.obj\"\n"), mDir / "s.toml"),
                    "[[obstacle]] #1.sequence_rate: missing required key");
    EXPECT_CONTAINS(
        errorOf(obstacle("file = \"plate.obj\"\nsequence_rate = 24\n"), mDir / "s.toml"),
        "[[obstacle]] #1.sequence_rate: only for a numbered sequence");
    EXPECT_CONTAINS(
        errorOf(obstacle("file = \"flag_####.obj\"\nsequence_rate = 0\n"), mDir / "s.toml"),
        "[[obstacle]] #1.sequence_rate");
    EXPECT_CONTAINS(
        errorOf(obstacle("file = \"flag_####.obj\"\nsequence_rate = 1e9\n"), mDir / "s.toml"),
        "[[obstacle]] #1.sequence_rate: at most");
}

TEST_F(SceneLoaderTest, MoreSourcesOrObstaclesThanTheRuntimeTakesAreRefusedAtLoad) {
    // They were refused only after the whole precompute, when the simulation was set up.
    const std::string source = "[[source]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.1\n";
    const std::string obstacle =
        "[[obstacle]]\nshape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0]]\n";
    std::string full = sceneFixture(k2d);
    const int base = int(std::count(full.begin(), full.end(), '\n'));
    for (int i = 0; i < maxSmokeEmitters; ++i) full += source;
    for (int i = 0; i < maxObstacles; ++i) full += obstacle;
    const SceneSpec scene = parseScene(full, "s.toml");
    EXPECT_EQ(scene.sources.size(), std::size_t(maxSmokeEmitters));
    EXPECT_EQ(scene.obstacles.size(), std::size_t(maxObstacles));
    EXPECT_GE(maxSmokeEmitters, 64) << "what users need";
    EXPECT_GE(maxObstacles, 64) << "what users need";

    const std::string more = std::to_string(maxSmokeEmitters + 1);
    std::string message = errorOf(full + source);
    EXPECT_CONTAINS(message, "[[source]]: " + more + " entries; at most " +
                                 std::to_string(maxSmokeEmitters) +
                                 " sources take part in a simulation");
    // The first entry past the limit: the sources' lines, then the obstacles', then it.
    EXPECT_CONTAINS(
        message,
        "(line " + std::to_string(base + 4 * maxSmokeEmitters + 4 * maxObstacles + 1) + ")");
    message = errorOf(full + obstacle);
    EXPECT_CONTAINS(message, "[[obstacle]]: " + std::to_string(maxObstacles + 1) +
                                 " entries; at most " + std::to_string(maxObstacles) +
                                 " obstacles take part in a simulation");
}

TEST_F(SceneLoaderTest, ASourceMayDriveTheAirAndMove) {
    const std::string source = "[[source]]\nshape = \"box\"\nmin = [0, 0]\nmax = [0.1, 0.2]\n";
    const SceneSpec scene = parseScene(sceneFixture(k2d) + source +
                                           "velocity = [0.5, -1]\npath = [[0, 0, 0], [1, 0.5, 0]]\n"
                                           "rotation = [[0, 0, 0, 1, 0], [1, 0, 0, 1, 90]]\n" +
                                           source,
                                       "s.toml");
    ASSERT_EQ(scene.sources.size(), 2u);
    EXPECT_EQ(scene.sources[0].velocity, (Vec3{0.5, -1.0, 0.0}));
    ASSERT_EQ(scene.sources[0].path.size(), 2u);
    EXPECT_EQ(scene.sources[0].path[1].second, (Vec3{0.5, 0.0, 0.0}));
    ASSERT_EQ(scene.sources[0].rotation.size(), 2u);
    EXPECT_EQ(scene.sources[0].rotation[1].degrees, 90.0);
    EXPECT_FALSE(scene.sources[1].velocity.has_value()) << "smoke alone unless asked";
    EXPECT_TRUE(scene.sources[1].path.empty()) << "still unless asked";
    EXPECT_CONTAINS(errorOf(sceneFixture(k2d) + source + "path = [[1, 0, 0], [0.5, 1, 0]]\n"),
                    "[[source]] #1 (box).path: key frame times must increase");
}

TEST_F(SceneLoaderTest, RandomInitialVelocityTakesEnergySeedAndBand) {
    const std::string base = sceneFixture(k2d) + kRandom;
    const SceneSpec all = parseScene(base + "energy = 0.5\nseed = 9\n", "s.toml");
    EXPECT_EQ(all.initial.energy, 0.5);
    EXPECT_EQ(all.initial.seed, 9u);
    EXPECT_FALSE(all.initial.band.has_value());
    const SceneSpec band = parseScene(base + "band = [3, 10]\n", "s.toml");
    ASSERT_TRUE(band.initial.band.has_value());
    EXPECT_EQ(*band.initial.band, (ModeRange{3, 10}));
}

TEST_F(SceneLoaderTest, NonFiniteNumbersAreRefusedForEveryFloatKey) {
    // TOML spells them nan, inf and -inf; each float key names itself when given one. X marks
    // where the value goes.
    const std::string two = sceneFixture(k2d), three = sceneFixture(k3d);
    const std::string square = sceneFixture(kSquare);
    const std::string mhd = two + kMhd;
    const std::string vortex2 = two + kVortices + "[[initial.vortex]]\n";
    const std::string vortex3 = three + kVortices + "[[initial.vortex]]\n";
    const std::string source = two + "[[source]]\nshape = \"ball\"\n";
    const std::string obstacle = two + "[[obstacle]]\n";
    const std::string domain3 = three + "[[domain]]\n";
    const std::pair<std::string, std::string> cases[] = {
        {replaced(square, "[0, 0]", "[0, X]"), "[grid].bounds_min[1]"},
        {replaced(square, "[1, 1]", "[X, 1]"), "[grid].bounds_max[0]"},
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
        {two + "[simulation]\ndt = X\n", "[simulation].dt"},
        {two + "[simulation]\nviscosity = X\n", "[simulation].viscosity"},
        {two + "[simulation]\nalpha = X\n", "[simulation].alpha"},
        {two + "[simulation]\nmhd = true\nmagnetic_diffusivity = X\n",
         "[simulation].magnetic_diffusivity"},
        {two + kRandom + "energy = X\n", "[initial].energy"},
        {two + kModes + "amplitudes = [[1, X]]\n", "[initial].amplitudes[0][1]"},
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
        {obstacle +
             "shape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0]]\nrotation = [[X, 0, 0, 1, 0]]\n",
         "[[obstacle]] #1.rotation time"},
        {obstacle +
             "shape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0]]\nrotation = [[0, 0, X, 1, 0]]\n",
         "[[obstacle]] #1.rotation axis"},
        {obstacle +
             "shape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0]]\nrotation = [[0, 0, 0, 1, X]]\n",
         "[[obstacle]] #1.rotation degrees"},
        {two + "[smoke]\nbuoyancy = X\n", "[smoke].buoyancy"},
    };
    for (const auto& [text, key] : cases) {
        const std::size_t x = text.find('X');
        ASSERT_NE(x, std::string::npos) << key;
        for (const std::string value : {"nan", "inf", "-inf"}) {
            const std::string message = errorOf(text.substr(0, x) + value + text.substr(x + 1));
            EXPECT_CONTAINS(message, key + ": must be finite, got " + value);
        }
    }
}

TEST_F(SceneLoaderTest, InitialSpeedsUpToTheCapAreAccepted) {
    // Energies are ½∫|u|² over the grid's box (2.2 x 2.2 x 1 here), so the cap is a mean speed,
    // scale-free in space (AbsurdEnergy and the other refusals past it are in the table).
    const std::string base = sceneFixture(k2d) + kRandom;
    const double volume = 2.2 * 2.2;
    const auto energyAt = [&](double speed) {
        return formatNumberForTest(0.5 * speed * speed * volume);
    };
    EXPECT_EQ(errorOf(base + "energy = " + energyAt(0.99e6) + "\n"), "");
    const std::string message = errorOf(base + "energy = " + energyAt(1.01e6) + "\n");
    EXPECT_CONTAINS(message, "[initial].energy: ");
    EXPECT_CONTAINS(message, "is a mean speed of 1e+06");
}
TEST_F(SceneLoaderTest, MagneticFieldIsRandomOrUniformAndChecked) {
    const std::string base = sceneFixture(k2d) + kMhd;
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
}

TEST_F(SceneLoaderTest, ForcingHoldsModesByPositionOrWaveNumber) {
    const std::string base = sceneFixture(k2d);
    const SceneSpec none = parseScene(base, "s.toml");
    EXPECT_FALSE(none.forcing.holds());
    const SceneSpec byPosition = parseScene(base + "[forcing]\nhold_modes = \"1-3,5\"\n", "s.toml");
    EXPECT_EQ(byPosition.forcing.holdModes, (std::vector<ModeRange>{{1, 3}, {5, 5}}));
    EXPECT_TRUE(byPosition.forcing.holds());
    const SceneSpec byKappa = parseScene(base + "[forcing]\nhold_below_kappa = 2.0\n", "s.toml");
    EXPECT_EQ(byKappa.forcing.holdBelowKappa, 2.0);
    EXPECT_TRUE(byKappa.forcing.holdModes.empty());

    // Every mode, however the ranges split them: refused at load, not after the precompute.
    for (const char* all : {"1-10", "1-5,6-10", "1,2-9,10", "1-4,5,6-10"})
        EXPECT_CONTAINS(errorOf(base + "[forcing]\nhold_modes = \"" + all + "\"\n"),
                        "[forcing].hold_modes: holds every mode of the basis: nothing would move");
    for (const char* some : {"1-9", "2-10", "1-4,6-10", "1,3-10"})
        EXPECT_TRUE(parseScene(base + "[forcing]\nhold_modes = \"" + some + "\"\n", "s.toml")
                        .forcing.holds())
            << some;
}

TEST_F(SceneLoaderTest, TheLinearizedRuleIsForFluids) {
    const std::string base = sceneFixture(k2d) + "[simulation]\n";
    EXPECT_EQ(parseScene(base + "integrator = \"linearized\"\n", "s.toml").simulation.integrator,
              Integrator::Linearized);
}

TEST_F(SceneLoaderTest, ModalAmplitudesAreRequiredAndChecked) {
    const std::string base = sceneFixture(k2d) + kModes;
    const SceneSpec scene =
        parseScene(base + "amplitudes = [[1, 0.5], [3, -0.2], [10, 2]]\n", "s.toml");
    const std::vector<std::pair<int, double>> expected{{1, 0.5}, {3, -0.2}, {10, 2.0}};
    EXPECT_EQ(scene.initial.amplitudes, expected);
}

TEST_F(SceneLoaderTest, VorticesAreReadIn2dAnd3d) {
    const std::string base2 = sceneFixture(k2d) + kVortices;
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

    const SceneSpec three =
        parseScene(sceneFixture(k3d) + kVortices3d + kRing + "normal = [1, 0, 0]\n", "s.toml");
    EXPECT_EQ(three.initial.energy, 0.7);
    ASSERT_EQ(three.initial.vortices.size(), 1u);
    EXPECT_EQ(three.initial.vortices[0].normal, (Vec3{1.0, 0.0, 0.0}));
    EXPECT_EQ(three.initial.vortices[0].ringRadius, 0.4);
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
    const fs::path file = write("huge.toml", sceneFixture(k2d));
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

TEST_F(SceneLoaderTest, DeeplyNestedTablesAreRefusedNotACrash) {
    // toml++ walks nested tables recursively: [a.a.a...] 100000 deep overflowed the stack.
    std::string deep = "[a";
    for (int i = 0; i < 100000; ++i) deep += ".a";
    EXPECT_CONTAINS(errorOf(sceneFixture(k2d) + deep + "]\n"),
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
    EXPECT_EQ(errorOf(sceneFixture(k2d) + path + "]\n"), "");
}

TEST_F(SceneLoaderTest, FileTextInMessagesIsPrintableAndShort) {
    // TOML escapes let a key or a value hold terminal commands; they were printed as they were.
    const std::string base = sceneFixture(k2d);
    std::string message = errorOf(base + "[output]\n\"\\u001b[2J\" = 1\n");
    EXPECT_CONTAINS(message, "[output].\\x1b[2J: unknown key");
    EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
    message = errorOf(base + "\"\\u001b]0;owned\\u0007\" = 1\n");
    EXPECT_CONTAINS(message, "\\x1b]0;owned\\x07: unknown key");
    message = errorOf(replaced(base, "velocity_modes = 10", "modes = \"1-3\\u001b[2J\""));
    EXPECT_CONTAINS(message, "bad mode list \"1-3\\x1b[2J\": unexpected character '\\x1b'");
    EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
    message = errorOf(base + "[simulation]\nintegrator = \"\\u009b31m\"\n");
    EXPECT_CONTAINS(message, "unknown value \"\\xc2\\x9b31m\"");

    // A megabyte-long value or key is cut, and a suggestion is not searched for in it.
    const std::string huge(1 << 20, '7');
    message = errorOf(replaced(base, "velocity_modes = 10", "modes = \"1-" + huge + "\""));
    EXPECT_LT(message.size(), 400u) << message.size() << " characters";
    EXPECT_CONTAINS(message, "...");
    message = errorOf(base + "[output]\n" + std::string(1 << 20, 'f') + " = 1\n");
    EXPECT_LT(message.size(), 400u) << message.size() << " characters";
    message = errorOf(base + "[simulation]\nintegrator = \"" + huge + "\"\n");
    EXPECT_LT(message.size(), 400u) << message.size() << " characters";
    EXPECT_CONTAINS(parseModeRangesError("1-3\x1b"), "\\x1b");
}

TEST_F(SceneLoaderTest, HugeArraysAreCountedNotEchoed) {
    std::string many = "[grid]\nresolution = [";
    for (int i = 0; i < 100000; ++i) many += "8, ";
    EXPECT_CONTAINS(errorOf(many + "8]\n"),
                    "[grid].resolution: expected 2 or 3 integers, got "
                    "100001 entries");
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

TEST(SceneLoaderPeriodic, PeriodicFlagsAreOnePerAxisAndDefaultToWalls) {
    // The refusals are rows of RefusedScene (OnePeriodicFlag and the next three).
    const std::string square = replaced(sceneFixture(kSquare), {basis("velocity_modes = 4")});
    const SceneSpec walls = parseScene(square, "walls.toml");
    EXPECT_FALSE(walls.grid.anyPeriodic());
    const SceneSpec explicitWalls =
        parseScene(replaced(square, {periodicFlags("[false, false]")}), "walls.toml");
    EXPECT_EQ(explicitWalls.grid, walls.grid);
}

TEST(SceneLoaderPeriodic, PeriodicAxesAreAcceptedAndCountTheirFacesOnce) {
    const std::string square = sceneFixture(kSquare);
    const SceneSpec channel = parseScene(
        replaced(square, {{"[8, 8]", "[8, 4]"},
                          {"bounds_max = [1, 1]", "bounds_max = [2, 1]\nperiodic = [true, false]"},
                          basis("velocity_modes = 4")}),
        "channel.toml");
    EXPECT_EQ(channel.grid.periodic, (std::array<bool, 3>{true, false, false}));
    const SceneSpec slab = parseScene(
        replaced(square,
                 {{"[8, 8]", "[4, 4, 4]"},
                  {"[0, 0]", "[0, 0, 0]"},
                  {"bounds_max = [1, 1]", "bounds_max = [1, 1, 1]\nperiodic = [true, false, true]"},
                  basis("velocity_modes = 4")}),
        "slab.toml");
    EXPECT_EQ(slab.grid.periodic, (std::array<bool, 3>{true, false, true}));
    // Mode 36 fits a walled 4 × 4 box (40 faces); the torus's refusal is
    // ModeBeyondTheFacesOfATorus.
    EXPECT_NO_THROW(parseScene(
        replaced(square, {{"[8, 8]", "[4, 4]"}, basis("velocity_modes = 36\nscalar_modes = 0")}),
        "box.toml"));
}

TEST(SceneLoaderOpen, OpenSidesAreNamedAndDefaultToWalls) {
    // The refusals are rows of RefusedScene (OpenNotAnArray and the next six).
    const std::string square = replaced(sceneFixture(kSquare), {basis("velocity_modes = 4")});
    EXPECT_FALSE(parseScene(square, "walls.toml").grid.anyOpen());
    const SceneSpec top =
        parseScene(replaced(square, {openSides("[\"y_max\", \"x_min\"]")}), "top.toml");
    EXPECT_EQ(top.grid.open, (std::array<bool, 6>{true, false, false, true, false, false}));
    EXPECT_FALSE(hasClosedFormVelocity(top));  // eigensolved: quarter waves have no closed form
    const SceneSpec box = parseScene(
        replaced(square, {{"[8, 8]", "[4, 4, 4]"},
                          {"[0, 0]", "[0, 0, 0]"},
                          {"bounds_max = [1, 1]", "bounds_max = [1, 1, 1]\nopen = [\"z_min\"]"}}),
        "box.toml");
    EXPECT_EQ(box.grid.open, (std::array<bool, 6>{false, false, false, false, true, false}));
}

// ---- surface scenes ([surface]) -----------------------------------------------------------------

constexpr const char* kSurface = "[surface]\nmesh = \"meshes/ball.obj\"\n";
constexpr const char* kBasis = "\n[basis]\nvelocity_modes = 10\n";

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
    EXPECT_FALSE(loadScene(write("grid.toml", sceneFixture(k2d))).isSurface());
}

TEST_F(SceneLoaderTest, SurfaceSceneRefusesTheGridsTablesAndKeys) {
    write("meshes/ball.obj", "v 0 0 0\n");
    const std::string surface = std::string(kSurface) + kBasis;
    const std::pair<std::string, std::string> refusals[] = {
        {sceneFixture(k3d) + kSurface,
         "[grid]: a scene is either a grid scene ([grid], [[domain]]) or a surface scene "
         "([surface]), not both"},
        {surface + "[[domain]]\nshape = \"ball\"\ncenter = [0, 0, 0]\nradius = 1\n",
         "[[domain]]: a scene is either a grid scene"},
        {surface + "[[obstacle]]\nshape = \"ball\"\nradius = 0.1\npath = [[0, 0, 0, 0]]\n",
         "[[obstacle]]: moving obstacles push on a grid's faces"},
        {surface + "[smoke]\nbuoyancy = 1.0\n", "[smoke]: buoyancy and the smoke grid"},
        {surface + "[[particles]]\nshape = \"ball\"\ncenter = [0, 0, 1]\nradius = 0.2\ncount = 3\n",
         "[[particles]]: particles are carried by a grid's velocity"},
        {surface + "[[source]]\nshape = \"ball\"\ncenter = [0, 0, 1]\nradius = 0.2\nvelocity = [1, "
                   "0, 0]\n",
         "[[source]] #1.velocity: a surface scene's sources add dye alone"},
        {surface + "[[source]]\nshape = \"ball\"\ncenter = [0, 0, 1]\nradius = 0.2\npath = [[0, 0, "
                   "0, 0]]\n",
         "[[source]] #1.path: a surface scene's sources stay still"},
        {surface + "[[source]]\nshape = \"mesh\"\nfile = \"meshes/ball.obj\"\n",
         "[[source]] #1.shape: a surface scene's sources are balls or boxes in space"},
        {std::string(kSurface) + "[basis]\nvelocity_modes = 4\nwall = \"no-slip\"\n",
         "[basis].wall: only for grid scenes"},
        {surface + "[wind]\nvelocity = [1, 0, 0]\n", "[wind]: a surface is closed"},
        {surface + "[[inflow]]\nshape = \"ball\"\n", "[[inflow]]: a surface is closed"},
        {surface + "[simulation]\nmhd = true\n",
         "[simulation].mhd: MHD is simulated in grid scenes only"},
        {surface + "[initial]\nvelocity = \"vortices\"\n",
         "[initial].velocity: vortices are projected on a grid"},
        {"[surface]\nmesh = \"meshes/ball.obj\"\nfile = \"x\"\n" + std::string(kBasis),
         "[surface].file: unknown key"},
        {"[surface]\nmesh = \"missing.obj\"\n" + std::string(kBasis),
         "[surface].mesh: no such file"},
        {"[surface]\nmesh = \"meshes/ball.stl\"\n" + std::string(kBasis),
         "[surface].mesh: only OBJ meshes are supported"},
    };
    for (const auto& [text, fragment] : refusals) {
        SCOPED_TRACE(text);
        EXPECT_CONTAINS(errorOf(text, mDir / "s.toml"), fragment);
    }
}

}  // namespace
}  // namespace modeflow
