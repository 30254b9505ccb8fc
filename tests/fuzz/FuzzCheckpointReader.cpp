/// Fuzz target: the run checkpoint reader. Inputs with the checkpoint magic are whole files;
/// others are bodies after the version, given the magic, version and a valid checksum so that
/// the decoder sees them.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "engine/core/BinaryCodec.h"
#include "engine/simulation/Checkpoint.h"
#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {
namespace {

constexpr std::string_view kMagic("MODEFLOW-RESUME\0", 16);

/// A checkpoint file around `body` (layout in Checkpoint.h).
std::string checkpointAround(std::string_view body) {
    ByteWriter file;
    file.values(kMagic.data(), kMagic.size());
    file.pod(std::uint32_t{7});  // the version (Checkpoint.cpp)
    file.values(body.data(), body.size());
    file.pod(checksum64(file.bytes()));
    return file.bytes();
}

template <typename Values>
bool sameBytes(const Values& a, const Values& b) {
    return a.size() == b.size() &&
           (a.size() == 0 || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

}  // namespace

bool checkpointReader(std::string_view bytes) {
    const auto input = scratchFile("input.resume", bytes.substr(0, kMagic.size()) == kMagic
                                                       ? std::string(bytes)
                                                       : checkpointAround(bytes));
    Checkpoint checkpoint;
    if (!acceptedOrRefused([&] { checkpoint = readCheckpoint(input); })) return false;
    const auto copy = input.parent_path() / "copy.resume";
    writeCheckpoint(copy, checkpoint);
    const Checkpoint again = readCheckpoint(copy);
    require(again.frame == checkpoint.frame && again.runHash == checkpoint.runHash &&
                std::memcmp(&again.time, &checkpoint.time, sizeof again.time) == 0 &&
                sameBytes(again.velocity, checkpoint.velocity) &&
                sameBytes(again.magnetic, checkpoint.magnetic) &&
                sameBytes(again.carry.heldRate, checkpoint.carry.heldRate) &&
                again.carry.warmRhs.size() == checkpoint.carry.warmRhs.size() &&
                again.carry.substeps == checkpoint.carry.substeps &&
                again.carry.easySteps == checkpoint.carry.easySteps &&
                sameBytes(again.smoke.density, checkpoint.smoke.density) &&
                sameBytes(again.smoke.temperature, checkpoint.smoke.temperature) &&
                sameBytes(again.smoke.fuel, checkpoint.smoke.fuel) &&
                sameBytes(again.smoke.flame, checkpoint.smoke.flame) &&
                sameBytes(again.particles.position, checkpoint.particles.position) &&
                sameBytes(again.particles.velocity, checkpoint.particles.velocity) &&
                again.particles.set == checkpoint.particles.set,
            "an accepted checkpoint does not survive a write and a read");
    for (std::size_t i = 0; i < again.carry.warmRhs.size(); ++i)
        require(sameBytes(again.carry.warmRhs[i], checkpoint.carry.warmRhs[i]),
                "an accepted warm start does not survive a write and a read");
    // What a resumed run relies on: every value it continues from is a number.
    for (const std::vector<double>* field :
         {&again.smoke.density, &again.smoke.temperature, &again.smoke.fuel, &again.smoke.flame})
        for (const double c : *field) require(std::isfinite(c), "an accepted smoke is not finite");
    return true;
}

}  // namespace modeflow::fuzz
