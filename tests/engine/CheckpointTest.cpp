/// The run checkpoint (`modeflow run --resume`): it round-trips bit for bit, files that are not
/// whole checkpoints are refused cheaply with a message, and a failed write says why.

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/AtomicFile.h"
#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"
#include "engine/simulation/Checkpoint.h"
#include "engine/simulation/ParticleMotion.h"
#include "tests/support/PeakMemory.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;
using testing::peakMemoryMiB;
using testing::TestFolder;

Checkpoint sample(std::size_t cells = 6) {
    Checkpoint c;
    c.frame = 12;
    c.time = 0.75;
    c.runHash = 0x0123456789abcdefull;
    c.velocity = Eigen::VectorXd::LinSpaced(5, -1.0, 1.0);
    c.magnetic = Eigen::VectorXd::LinSpaced(5, 2.0, 3.0);
    c.carry.heldRate = Eigen::VectorXd::LinSpaced(5, -4.0, 0.5);
    // A device midpoint run's warm start: two right-hand sides of the state [v; F] (10 values).
    c.carry.warmRhs = {Eigen::VectorXd::LinSpaced(10, 0.5, 1.5),
                       Eigen::VectorXd::LinSpaced(10, -2.0, 2.0)};
    c.carry.substeps = 4;
    c.carry.easySteps = 17;
    c.smoke.density.assign(cells, 0.25);
    c.smoke.temperature.assign(cells, 1.5);
    c.particles.position = {0.1, 0.2, 0.3, -0.4, 0.5, 0.0};
    c.particles.velocity = {1.0, 0.0, -1.0, 0.25, 0.5, 0.0};
    c.particles.set = {0, 3};
    return c;
}

std::string readError(const fs::path& file) {
    try {
        readCheckpoint(file);
    } catch (const Error& e) {
        return e.what();
    }
    return "accepted";
}

std::string writeError(const fs::path& file, const Checkpoint& checkpoint) {
    try {
        writeCheckpoint(file, checkpoint);
    } catch (const Error& e) {
        return e.what();
    }
    return "written";
}

/// The bytes of a checkpoint with a fresh checksum after `edit` changed them (the checksum is the
/// last 8 bytes, over everything before).
void rewrite(const fs::path& file, const std::function<void(std::string&)>& edit) {
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    bytes.resize(bytes.size() - 8);
    edit(bytes);
    const std::uint64_t checksum = checksum64(bytes);
    bytes.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(CheckpointTest, RoundTripsBitForBit) {
    const TestFolder folder;
    writeCheckpoint(folder / "run.resume", sample());
    const Checkpoint read = readCheckpoint(folder / "run.resume");
    EXPECT_EQ(read.frame, 12);
    EXPECT_EQ(read.time, 0.75);
    EXPECT_EQ(read.runHash, sample().runHash);
    EXPECT_EQ(read.velocity, sample().velocity);
    EXPECT_EQ(read.magnetic, sample().magnetic);
    EXPECT_EQ(read.carry.heldRate, sample().carry.heldRate);
    EXPECT_EQ(read.carry.warmRhs, sample().carry.warmRhs);
    EXPECT_EQ(read.carry.substeps, 4);
    EXPECT_EQ(read.carry.easySteps, 17);
    EXPECT_EQ(read.smoke.density, sample().smoke.density);
    EXPECT_EQ(read.smoke.temperature, sample().smoke.temperature);
    EXPECT_EQ(read.particles.position, sample().particles.position);
    EXPECT_EQ(read.particles.velocity, sample().particles.velocity);
    EXPECT_EQ(read.particles.set, sample().particles.set);
}

TEST(CheckpointTest, AHugeFileIsRefusedByItsHeaderWithoutReadingIt) {
    const TestFolder folder;
    const fs::path file = folder / "big.resume";
    std::ofstream(file) << "not a checkpoint";
    fs::resize_file(file, std::uintmax_t{1} << 30);  // sparse: no disk used
    const long before = peakMemoryMiB();
    EXPECT_NE(readError(file).find("not a modeflow checkpoint"), std::string::npos)
        << readError(file);
    EXPECT_LT(peakMemoryMiB() - before, 64) << "MiB more at the peak: the file was read whole";
}

TEST(CheckpointTest, FoldersAndDevicesAreRefusedByName) {
    const TestFolder folder;
    EXPECT_EQ(readError(folder.path()),
              folder.path().string() + ": is a directory, not a checkpoint");
    EXPECT_EQ(readError("/dev/zero"), "/dev/zero: is a character device, not a checkpoint");
    EXPECT_EQ(readError(folder / "missing.resume"),
              (folder / "missing.resume").string() + ": no such checkpoint");
}

TEST(CheckpointTest, WellFormedNonsenseIsRefused) {
    const TestFolder folder;
    const fs::path file = folder / "run.resume";
    const auto damaged = [&](const std::function<void(std::string&)>& edit) {
        writeCheckpoint(file, sample());
        rewrite(file, edit);
        return readError(file);
    };
    EXPECT_EQ(damaged([](std::string&) {}), "accepted") << "the undamaged checkpoint";
    // Layout: magic (16) | version (4) | frame (4) | run hash (8) | time (8) | ...
    EXPECT_NE(
        damaged([](std::string& b) { std::memset(b.data() + 20, 0xff, 4); }).find("frame number"),
        std::string::npos);
    EXPECT_NE(damaged([](std::string& b) {
                  const double nan = std::numeric_limits<double>::quiet_NaN();
                  std::memcpy(b.data() + 32, &nan, 8);
              }).find("its time is not a non-negative number"),
              std::string::npos);
    EXPECT_NE(damaged([](std::string& b) { b += "trailing"; }).find("bytes follow its particles"),
              std::string::npos);
    EXPECT_NE(damaged([](std::string& b) { b.resize(b.size() - 8); }).find("truncated"),
              std::string::npos);
    // A held rate is none or one value per mode; a warm start none, one or two of the state's.
    Checkpoint odd = sample();
    odd.carry.heldRate = Eigen::VectorXd::Ones(4);
    writeCheckpoint(file, odd);
    EXPECT_NE(readError(file).find("its held rate and velocity sizes differ"), std::string::npos)
        << readError(file);
    odd.carry.heldRate.resize(0);
    writeCheckpoint(file, odd);
    EXPECT_EQ(readCheckpoint(file).carry.heldRate.size(), 0);
    odd.carry.warmRhs.push_back(odd.carry.warmRhs[0]);
    writeCheckpoint(file, odd);
    EXPECT_NE(readError(file).find("more than two right-hand sides"), std::string::npos)
        << readError(file);
    odd.carry.warmRhs = {Eigen::VectorXd::Ones(5)};
    writeCheckpoint(file, odd);
    EXPECT_NE(readError(file).find("its warm start and state sizes differ"), std::string::npos)
        << readError(file);
    odd.carry.warmRhs.clear();
    for (const auto& [substeps, easy] :
         {std::pair{0, 0}, std::pair{1 << 20, 0}, std::pair{1, -1}}) {
        odd.carry.substeps = substeps;
        odd.carry.easySteps = easy;
        writeCheckpoint(file, odd);
        EXPECT_NE(readError(file).find("its substep count is out of range"), std::string::npos)
            << readError(file);
    }
    // Modal values no step can continue from.
    const auto withNan = [](Checkpoint bad,
                            const std::function<Eigen::VectorXd&(Checkpoint&)>& part) {
        part(bad)[2] = std::numeric_limits<double>::quiet_NaN();
        return bad;
    };
    for (const auto& part : std::vector<std::function<Eigen::VectorXd&(Checkpoint&)>>{
             [](Checkpoint& c) -> Eigen::VectorXd& { return c.velocity; },
             [](Checkpoint& c) -> Eigen::VectorXd& { return c.magnetic; },
             [](Checkpoint& c) -> Eigen::VectorXd& { return c.carry.heldRate; },
             [](Checkpoint& c) -> Eigen::VectorXd& { return c.carry.warmRhs[1]; }}) {
        writeCheckpoint(file, withNan(sample(), part));
        EXPECT_NE(readError(file).find("is not finite"), std::string::npos) << readError(file);
    }
    // Particles no step can continue from.
    Checkpoint scattered = sample();
    scattered.particles.velocity[4] = std::numeric_limits<double>::infinity();
    writeCheckpoint(file, scattered);
    EXPECT_NE(
        readError(file).find("its particles: particle 1's position or velocity is not finite"),
        std::string::npos)
        << readError(file);
    // A particle that left through an open side (its position NaN, at rest) is no such particle.
    Checkpoint left = sample();
    for (int a = 0; a < 3; ++a) {
        left.particles.position[std::size_t(a)] = kParticleLeft;
        left.particles.velocity[std::size_t(a)] = 0.0;
    }
    writeCheckpoint(file, left);
    EXPECT_NO_THROW(readCheckpoint(file));
    left.particles.velocity[0] = 1.0;  // moving, nowhere: diverged
    writeCheckpoint(file, left);
    EXPECT_NE(readError(file).find("particle 0's position or velocity is not finite"),
              std::string::npos)
        << readError(file);
    scattered = sample();
    scattered.particles.set.push_back(1);
    writeCheckpoint(file, scattered);
    EXPECT_NE(readError(file).find("3 particles with 6 position and 6 velocity values"),
              std::string::npos)
        << readError(file);
    // Smoke no step can continue from: refused naming the file, not blamed on a divergence later.
    for (std::vector<double> SmokeFields::*field :
         {&SmokeFields::density, &SmokeFields::temperature})
        for (const double bad :
             {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
            Checkpoint smoky = sample();
            (smoky.smoke.*field)[3] = bad;
            writeCheckpoint(file, smoky);
            const std::string why = readError(file);
            EXPECT_EQ(why, "checkpoint " + file.string() + ": its smoke " +
                               (field == &SmokeFields::density ? "density" : "temperature") +
                               " is not finite; delete it to start the run afresh");
        }
}

TEST(CheckpointTest, AFailedWriteSaysWhyAndLeavesNoPartialFile) {
    const TestFolder folder;
    // Renaming over a folder fails.
    fs::create_directories(folder / "taken.resume" / "inside");
    const std::string renaming = writeError(folder / "taken.resume", sample());
    EXPECT_NE(renaming.find("cannot write checkpoint " + (folder / "taken.resume").string() +
                            ": cannot rename " +
                            temporaryPathFor(folder / "taken.resume").string() + " over it"),
              std::string::npos)
        << renaming;
    EXPECT_EQ(renaming.find("Success"), std::string::npos) << renaming;

    // A write past the file size limit fails with EFBIG, as a full disk fails with ENOSPC.
    rlimit saved{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
    const auto previous = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved;
    limited.rlim_cur = 4096;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
    const std::string writing = writeError(folder / "big.resume", sample(10000));
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
    EXPECT_EQ(writing,
              "cannot write checkpoint " + (folder / "big.resume").string() + ": File too large");

    for (const auto& entry : fs::directory_iterator(folder.path()))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << entry.path();
}

}  // namespace
}  // namespace modeflow
