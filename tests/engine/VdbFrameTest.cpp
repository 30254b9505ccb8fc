/// @file VdbFrameTest.cpp
/// VDB frames (engine/output/VdbFrame): a 2D and a 3D frame on non-cubic cells at smoke scale 2
/// round-trip through the file (grid names, classes and types, voxel centres at the smoke cell
/// centres, values exact in float32 and within half precision, inactive below the threshold and
/// outside the fluid mask, vel equal to the MAC sample, metadata; an MHD frame's magnetic grid
/// sampled like vel; periodic frames say which axes wrap), and the write is atomic: a
/// missing or read-only folder, a directory in the way and a full disk each throw an Error naming
/// the file and leave neither the frame nor a temporary file behind.

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"
#include "engine/output/VdbFrame.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

/// The inputs of one frame, owned (VdbFrame only borrows them).
struct FrameData {
    MacGrid basis;
    MacGrid smoke;
    std::vector<float> density;
    std::vector<double> temperature;
    std::vector<double> faces;
    std::vector<std::uint8_t> mask;
    double threshold = 1e-4;

    VdbFrame frame(bool halfFloat = false) const {
        VdbFrame f;
        f.smokeGrid = smoke;
        f.basisGrid = basis;
        f.density = density;
        f.temperature = temperature;
        f.faceVelocity = faces;
        f.fluidMask = mask;
        f.frame = 17;
        f.time = 0.85;
        f.sceneHash = "3f2a9c0e";
        f.modeflowVersion = "0.1.0";
        f.options.halfFloat = halfFloat;
        f.options.activityThreshold = threshold;
        return f;
    }
    Vec3 centre(int i, int j, int k) const {
        return {smoke.cellCentre(0, i), smoke.cellCentre(1, j),
                smoke.dim == 3 ? smoke.cellCentre(2, k) : 0.0};
    }
};

/// Non-cubic cells, smoke scale 2; every kind of cell present: masked-out cells holding smoke,
/// values below the threshold (and exactly 0), negative temperatures, slow velocity regions.
FrameData makeFrame(int dim, std::array<bool, 3> periodic = {false, false, false}) {
    FrameData d;
    d.basis.dim = dim;
    d.basis.cells = dim == 3 ? std::array<int, 3>{4, 3, 2} : std::array<int, 3>{5, 3, 1};
    d.basis.origin = {-1.0, 0.5, dim == 3 ? -0.25 : 0.0};
    d.basis.spacing = {0.5, 0.3, dim == 3 ? 0.2 : 1.0};
    d.basis.periodic = periodic;
    d.smoke = d.basis.refined(2);
    const auto cells = static_cast<std::size_t>(d.smoke.cellCount());
    d.density.resize(cells);
    d.temperature.resize(dim == 3 ? cells : 0);
    d.mask.resize(cells);
    for (int k = 0; k < d.smoke.cells[2]; ++k)
        for (int j = 0; j < d.smoke.cells[1]; ++j)
            for (int i = 0; i < d.smoke.cells[0]; ++i) {
                const auto c = static_cast<std::size_t>(d.smoke.cellIndex(i, j, k));
                d.mask[c] = (i + 2 * j + 3 * k) % 7 != 0;
                d.density[c] = c % 5 == 0 ? 5e-5f : c % 11 == 0 ? 0.0f : 0.1f + 0.013f * float(c);
                if (dim == 3)
                    d.temperature[c] = c % 4 == 0 ? -2e-5 : 0.7 * std::sin(0.37 * double(c));
            }
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    d.faces.resize(static_cast<std::size_t>(d.basis.faceTotal()));
    for (double& f : d.faces) f = u(rng);
    // Faces of the first basis column barely move, so some cells fall below the threshold.
    for (int axis = 0; axis < dim; ++axis)
        for (int k = 0; k < d.basis.faceExtent(axis)[2]; ++k)
            for (int j = 0; j < d.basis.faceExtent(axis)[1]; ++j)
                for (int i = 0; i < 2; ++i) d.faces[d.basis.faceIndex(axis, i, j, k)] *= 1e-6;
    return d;
}

class VdbFrameTest : public ::testing::Test {
protected:
    /// Names of everything in `folder` (to spot leftover temporary files).
    static std::vector<std::string> entries(const fs::path& folder) {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(folder))
            names.push_back(e.path().filename().string());
        return names;
    }
    testing::TestFolder mFolder;
    const fs::path mDir = mFolder.path();
};

/// Everything a reader sees of one written frame, checked cell by cell.
void checkRoundTrip(const FrameData& d, const fs::path& file, bool halfFloat) {
    const VdbFrameInfo info = readVdbFrameInfo(file);
    const int dim = d.smoke.dim;
    ASSERT_EQ(info.grids.size(), dim == 3 ? 3u : 2u);
    EXPECT_EQ(info.grid("temperature") != nullptr, dim == 3);
    for (const VdbGridInfo& g : info.grids) {
        SCOPED_TRACE(g.name);
        const bool isVel = g.name == "vel";
        EXPECT_EQ(g.gridClass, isVel ? "unknown" : "fog volume");
        EXPECT_EQ(g.valueType, isVel ? "vec3s" : "float");
        if (isVel) {
            EXPECT_EQ(g.vectorType, "contravariant relative");
            EXPECT_TRUE(g.valuesInWorldSpace);
        }
        EXPECT_EQ(g.savedAsHalf, halfFloat);
        const double depth =
            dim == 3 ? d.smoke.spacing[2] : std::min(d.smoke.spacing[0], d.smoke.spacing[1]);
        EXPECT_DOUBLE_EQ(g.voxelSize[0], d.smoke.spacing[0]);
        EXPECT_DOUBLE_EQ(g.voxelSize[1], d.smoke.spacing[1]);
        EXPECT_DOUBLE_EQ(g.voxelSize[2], depth);
        for (int k = 0; k < d.smoke.cells[2]; ++k)
            for (int j = 0; j < d.smoke.cells[1]; ++j)
                for (int i = 0; i < d.smoke.cells[0]; ++i) {
                    const Vec3 world = g.indexToWorld(i, j, k), centre = d.centre(i, j, k);
                    for (int a = 0; a < 3; ++a)
                        EXPECT_NEAR(world[a], centre[a], 1e-14) << i << j << k;
                }
    }
    EXPECT_EQ(info.frame, 17);
    EXPECT_EQ(info.time, 0.85);
    EXPECT_EQ(info.sceneHash, "3f2a9c0e");
    EXPECT_EQ(info.modeflowVersion, "0.1.0");
    EXPECT_EQ(info.creator, "modeflow");

    std::vector<Vec3> centres;
    for (int k = 0; k < d.smoke.cells[2]; ++k)
        for (int j = 0; j < d.smoke.cells[1]; ++j)
            for (int i = 0; i < d.smoke.cells[0]; ++i) centres.push_back(d.centre(i, j, k));
    // Exact in float32; half rounds to 11 significant bits, and to steps of 2^-24 below 2^-14
    // (a vel component far smaller than the speed).
    const auto expectStored = [&](double got, double want, const std::string& what) {
        if (halfFloat) {
            EXPECT_NEAR(got, want, std::abs(want) * 0x1p-11 + 0x1p-25) << what;
        } else {
            EXPECT_EQ(got, double(float(want))) << what;
        }
    };
    int rounded = 0;  // values that float32 keeps but half does not: proof of half storage
    const auto checkScalar = [&](const char* name, const auto& values) {
        const std::vector<VdbSample> samples = sampleVdbGrid(file, name, centres);
        std::int64_t active = 0;
        for (std::size_t c = 0; c < centres.size(); ++c) {
            const std::string what = std::string(name) + " at cell " + std::to_string(c);
            const bool wantActive = d.mask[c] && std::abs(double(values[c])) >= d.threshold;
            EXPECT_EQ(samples[c].active, wantActive)
                << what << " value " << values[c] << " mask " << int(d.mask[c]);
            if (wantActive) {
                expectStored(samples[c].value[0], values[c], what);
                rounded += samples[c].value[0] != double(float(values[c]));
            } else {
                EXPECT_EQ(samples[c].value[0], 0.0) << what;
            }
            active += wantActive;
        }
        EXPECT_EQ(info.grid(name)->activeVoxels, active) << name;
        EXPECT_GT(active, 0) << name;
        EXPECT_LT(active, std::int64_t(centres.size())) << name;
    };
    checkScalar("density", d.density);
    if (dim == 3) checkScalar("temperature", d.temperature);
    EXPECT_EQ(rounded > 0, halfFloat) << rounded << " values rounded";

    const std::vector<VdbSample> vel = sampleVdbGrid(file, "vel", centres);
    std::int64_t active = 0, slow = 0;
    for (std::size_t c = 0; c < centres.size(); ++c) {
        const Vec3 want = sampleVelocity(d.basis, std::span<const double>(d.faces), centres[c]);
        const double speed = std::sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
        const bool wantActive = d.mask[c] && speed >= d.threshold;
        const std::string what = "vel at cell " + std::to_string(c);
        EXPECT_EQ(vel[c].active, wantActive) << what << " speed " << speed;
        for (int a = 0; a < 3; ++a) {
            if (wantActive) {
                expectStored(vel[c].value[a], want[a], what);
            } else {
                EXPECT_EQ(vel[c].value[a], 0.0) << what;
            }
        }
        if (dim == 2) {
            EXPECT_EQ(vel[c].value[2], 0.0) << what;
        }
        active += wantActive;
        slow += d.mask[c] && !wantActive;
    }
    EXPECT_EQ(info.grid("vel")->activeVoxels, active);
    EXPECT_GT(slow, 0)
        << "no fluid cell fell below the velocity threshold: the test lost its point";
}

TEST_F(VdbFrameTest, FramesRoundTripOnNonCubicCellsInFloatAndHalf) {
    for (const int dim : {2, 3})
        for (const bool half : {false, true}) {
            SCOPED_TRACE(std::to_string(dim) + "D" + (half ? " half" : " float"));
            const FrameData d = makeFrame(dim);
            const fs::path file = mDir / frameFileName("scene", dim * 10 + half);
            writeVdbFrame(file, d.frame(half));
            checkRoundTrip(d, file, half);
        }
    // Only the frames: no temporary file left over.
    EXPECT_EQ(entries(mDir).size(), 4u);
}

TEST_F(VdbFrameTest, PeriodicFramesSayWhichAxesWrapAndOtherwiseKeepTheContract) {
    // modeflow_periodic on the file and every grid of a periodic frame (the velocity sampled
    // across the seam, as the runtime does); walled frames carry none.
    for (const auto& [dim, periodic] : {std::pair{2, std::array<bool, 3>{true, false, false}},
                                        std::pair{3, std::array<bool, 3>{false, true, true}}}) {
        SCOPED_TRACE(std::to_string(dim) + "D");
        const FrameData d = makeFrame(dim, periodic);
        const fs::path file = mDir / frameFileName("periodic", dim);
        writeVdbFrame(file, d.frame());
        checkRoundTrip(d, file, false);
        const VdbFrameInfo info = readVdbFrameInfo(file);
        ASSERT_TRUE(info.periodic.has_value());
        EXPECT_EQ(*info.periodic, periodic);
        for (const VdbGridInfo& g : info.grids) EXPECT_EQ(g.periodic, info.periodic) << g.name;
    }
    FrameData mixed = makeFrame(2, {true, false, false});
    mixed.smoke.periodic[0] = false;
    EXPECT_THROW(writeVdbFrame(mDir / "mixed.vdb", mixed.frame()), Error);
    const fs::path walled = mDir / frameFileName("walled", 0);
    writeVdbFrame(walled, makeFrame(3).frame());
    const VdbFrameInfo info = readVdbFrameInfo(walled);
    EXPECT_FALSE(info.periodic.has_value());
    for (const VdbGridInfo& g : info.grids) EXPECT_FALSE(g.periodic.has_value()) << g.name;
}

TEST_F(VdbFrameTest, MhdFramesCarryTheMagneticFieldLikeTheVelocity) {
    for (const int dim : {2, 3}) {
        SCOPED_TRACE(std::to_string(dim) + "D");
        const FrameData d = makeFrame(dim);
        // Another face field than the velocity, so a mix-up of the two shows.
        std::vector<double> magnetic(d.faces.size());
        for (std::size_t f = 0; f < magnetic.size(); ++f)
            magnetic[f] = 0.5 - 0.9 * d.faces[magnetic.size() - 1 - f];
        VdbFrame frame = d.frame();
        frame.faceMagnetic = magnetic;
        const fs::path file = mDir / frameFileName("mhd", dim);
        writeVdbFrame(file, frame);

        const VdbFrameInfo info = readVdbFrameInfo(file);
        ASSERT_EQ(info.grids.size(), dim == 3 ? 4u : 3u);
        const VdbGridInfo* grid = info.grid("magnetic");
        ASSERT_NE(grid, nullptr);
        EXPECT_EQ(grid->valueType, "vec3s");
        EXPECT_EQ(grid->vectorType, info.grid("vel")->vectorType);
        EXPECT_TRUE(grid->valuesInWorldSpace);
        EXPECT_EQ(grid->indexToWorldMatrix, info.grid("vel")->indexToWorldMatrix);

        std::vector<Vec3> centres;
        for (int k = 0; k < d.smoke.cells[2]; ++k)
            for (int j = 0; j < d.smoke.cells[1]; ++j)
                for (int i = 0; i < d.smoke.cells[0]; ++i) centres.push_back(d.centre(i, j, k));
        const std::vector<VdbSample> stored = sampleVdbGrid(file, "magnetic", centres);
        std::int64_t active = 0;
        for (std::size_t c = 0; c < centres.size(); ++c) {
            const Vec3 want =
                sampleVelocity(d.basis, std::span<const double>(magnetic), centres[c]);
            const double size =
                std::sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
            const bool wantActive = d.mask[c] && size >= d.threshold;
            EXPECT_EQ(stored[c].active, wantActive) << "cell " << c;
            for (int a = 0; a < 3; ++a)
                EXPECT_EQ(stored[c].value[a], wantActive ? double(float(want[a])) : 0.0)
                    << "cell " << c;
            active += wantActive;
        }
        EXPECT_EQ(grid->activeVoxels, active);
        EXPECT_GT(active, 0);
    }
}

TEST_F(VdbFrameTest, DoubleDensityAndEmptyMaskWork) {
    FrameData d = makeFrame(3);
    const std::vector<double> density(d.density.begin(), d.density.end());
    VdbFrame frame = d.frame();
    frame.density = density;
    frame.fluidMask = {};  // the whole box is fluid
    writeVdbFrame(mDir / "f.vdb", frame);
    std::int64_t active = 0;
    for (const double v : density) active += std::abs(v) >= 1e-4;
    EXPECT_EQ(readVdbFrameInfo(mDir / "f.vdb").grid("density")->activeVoxels, active);
}

TEST_F(VdbFrameTest, FrameFileNamesHaveFourDigitsOrMore) {
    EXPECT_EQ(frameFileName("smoke", 1), "smoke_0001.vdb");
    EXPECT_EQ(frameFileName("smoke", 0), "smoke_0000.vdb");
    EXPECT_EQ(frameFileName("smoke", 12345), "smoke_12345.vdb");
    EXPECT_THROW(frameFileName("smoke", -1), Error);
    EXPECT_THROW(frameFileName("", 1), Error);
}

/// Runs `write`, expects an Error whose message names `file` (and `cause` when given).
template <typename F>
void expectWriteError(F write, const fs::path& file, const std::string& cause = "") {
    try {
        write();
        FAIL() << "no error writing " << file;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(file.string()), std::string::npos) << message;
        EXPECT_NE(message.find(cause), std::string::npos) << message;
        std::cout << "  message: " << message << "\n";
    }
}

TEST_F(VdbFrameTest, MissingFolderThrowsAndWritesNothing) {
    const FrameData d = makeFrame(2);
    const fs::path file = mDir / "missing" / "scene_0001.vdb";
    expectWriteError([&] { writeVdbFrame(file, d.frame()); }, file, "does not exist");
    EXPECT_FALSE(fs::exists(mDir / "missing"));
    EXPECT_TRUE(entries(mDir).empty());
}

TEST_F(VdbFrameTest, ReadOnlyFolderThrowsAndWritesNothing) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
    const FrameData d = makeFrame(2);
    fs::permissions(mDir, fs::perms::owner_read | fs::perms::owner_exec);
    const fs::path file = mDir / "scene_0001.vdb";
    expectWriteError([&] { writeVdbFrame(file, d.frame()); }, file, "Permission denied");
    fs::permissions(mDir, fs::perms::owner_all);
    EXPECT_TRUE(entries(mDir).empty());
}

TEST_F(VdbFrameTest, FailedRenameLeavesNoTemporaryFile) {
    const FrameData d = makeFrame(3);
    const fs::path file = mDir / "scene_0001.vdb";
    fs::create_directory(file);  // the rename over it fails after the whole frame was written
    expectWriteError([&] { writeVdbFrame(file, d.frame()); }, file, "rename");
    EXPECT_TRUE(fs::is_directory(file));
    EXPECT_EQ(entries(mDir), std::vector<std::string>{"scene_0001.vdb"});
}

TEST_F(VdbFrameTest, FullDiskLeavesNoFrameAndNoTemporaryFile) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    const FrameData d = makeFrame(3);
    const fs::path file = mDir / "scene_0001.vdb";
    // The temporary file's name, pointed at a device whose every write fails with ENOSPC.
    fs::create_symlink("/dev/full", mDir / ("scene_0001.vdb.tmp-" + std::to_string(::getpid())));
    expectWriteError([&] { writeVdbFrame(file, d.frame()); }, file, "No space left on device");
    EXPECT_TRUE(entries(mDir).empty());
}

TEST_F(VdbFrameTest, FailedWriteKeepsThePreviousFrame) {
    FrameData d = makeFrame(2);
    const fs::path file = mDir / "scene_0001.vdb";
    writeVdbFrame(file, d.frame());
    VdbFrame bad = d.frame();
    bad.frame = 99;
    d.density.pop_back();
    bad.density = d.density;
    expectWriteError([&] { writeVdbFrame(file, bad); }, file,
                     "density has 59 values for 60 smoke cells");
    EXPECT_EQ(readVdbFrameInfo(file).frame, 17);
    EXPECT_EQ(entries(mDir).size(), 1u);
    // A good frame replaces it.
    const FrameData again = makeFrame(2);
    VdbFrame next = again.frame();
    next.frame = 18;
    writeVdbFrame(file, next);
    EXPECT_EQ(readVdbFrameInfo(file).frame, 18);
    EXPECT_EQ(entries(mDir).size(), 1u);
}

TEST_F(VdbFrameTest, NonFiniteValuesAreRefused) {
    FrameData d = makeFrame(3);
    d.density[5] = std::nanf("");
    expectWriteError([&] { writeVdbFrame(mDir / "a.vdb", d.frame()); }, mDir / "a.vdb",
                     "density is not finite");
    d = makeFrame(3);
    d.faces[3] = INFINITY;
    expectWriteError([&] { writeVdbFrame(mDir / "b.vdb", d.frame()); }, mDir / "b.vdb",
                     "face velocity is not finite");
    d = makeFrame(2);
    std::vector<double> magnetic(d.faces.size(), 0.0);
    magnetic[1] = std::nan("");
    VdbFrame frame = d.frame();
    frame.faceMagnetic = magnetic;
    expectWriteError([&] { writeVdbFrame(mDir / "c.vdb", frame); }, mDir / "c.vdb",
                     "magnetic field is not finite");
    EXPECT_TRUE(entries(mDir).empty());
}

TEST_F(VdbFrameTest, ReadingAMissingOrBrokenFileThrows) {
    EXPECT_THROW(readVdbFrameInfo(mDir / "none.vdb"), Error);
    std::ofstream(mDir / "junk.vdb", std::ios::binary) << "not a vdb file at all";
    EXPECT_THROW(readVdbFrameInfo(mDir / "junk.vdb"), Error);
    // A frame cut short, as a crash without the atomic rename would leave it.
    const FrameData d = makeFrame(3);
    writeVdbFrame(mDir / "whole.vdb", d.frame());
    const auto bytes = fs::file_size(mDir / "whole.vdb");
    fs::copy_file(mDir / "whole.vdb", mDir / "cut.vdb");
    fs::resize_file(mDir / "cut.vdb", bytes / 2);
    EXPECT_THROW(readVdbFrameInfo(mDir / "cut.vdb"), Error);
    const Vec3 origin{0.0, 0.0, 0.0};
    EXPECT_THROW(sampleVdbGrid(mDir / "whole.vdb", "smoke", std::span(&origin, 1)), Error);
}

}  // namespace
}  // namespace modeflow
