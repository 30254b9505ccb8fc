#include "engine/simulation/Checkpoint.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/core/AtomicFile.h"
#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"
#include "engine/core/InputFile.h"
#include "engine/simulation/ParticleEmission.h"

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W',
                             '-', 'R', 'E', 'S', 'U', 'M', 'E', '\0'};
/// 2: the magnetic field after the velocity; 3: XXH3; 4: the held rate after the field; 5: the
/// whole step carry (warm start, substeps) in its place; 6: the particles after the smoke; 7: the
/// fuel and flame after the temperature (empty without fire).
constexpr std::uint32_t kVersion = 7;
/// The most warm-start vectors a stepper holds (StepCarry::warmRhs).
constexpr std::uint64_t kMaxWarmRhs = 2;
/// The most modal substeps a run takes per step (device::Simulation).
constexpr std::uint32_t kMaxSubsteps = 1u << 10;
/// The largest checkpoint read (64 GiB): the modal state and two fields of the largest smoke grid a
/// scene may ask for fit, and a damaged file cannot make the reader ask for terabytes.
constexpr std::uintmax_t kMaxCheckpointBytes = std::uintmax_t{1} << 36;
/// Magic, version, frame, run hash, time: what is checked before the bulk is read.
constexpr std::size_t kHeaderBytes = sizeof kMagic + 4 + 4 + 8 + 8;

std::string refusal(const std::filesystem::path& path, std::string_view why) {
    return "checkpoint " + path.string() + ": " + std::string(why) +
           "; delete it to start the run afresh";
}

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view why) {
    throw Error(refusal(path, why));
}

/// The whole file, its magic and version checked before the rest is read: a file that is no
/// checkpoint is refused without reading its bulk.
std::string readCheckpointBytes(const std::filesystem::path& path) {
    const std::uintmax_t size = inputFileSize(path, "checkpoint", kMaxCheckpointBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, std::string("cannot be opened (") + std::strerror(errno) + ")");
    std::string bytes(std::min<std::uintmax_t>(size, kHeaderBytes), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        fail(path, "not a modeflow checkpoint");
    std::uint32_t version = 0;
    if (bytes.size() >= sizeof kMagic + sizeof version)
        std::memcpy(&version, bytes.data() + sizeof kMagic, sizeof version);
    if (version != kVersion) fail(path, "written by another modeflow version");
    if (size < kHeaderBytes + sizeof(std::uint64_t)) fail(path, "truncated");
    try {
        bytes.resize(std::size_t(size));
    } catch (const std::bad_alloc&) {
        fail(path, "not enough memory to read its " + std::to_string(size) + " bytes");
    }
    in.read(bytes.data() + kHeaderBytes, std::streamsize(size - kHeaderBytes));
    if (!in) fail(path, "could not be read to its end (it changed while it was read?)");
    return bytes;
}

Eigen::VectorXd modalVector(ByteReader& reader) {
    const std::vector<double> values = reader.vector<double>();
    return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
}

}  // namespace

void writeCheckpoint(const std::filesystem::path& path, const Checkpoint& checkpoint) {
    ByteWriter w;
    w.pod(kMagic);
    w.pod(kVersion);
    w.pod(std::uint32_t(checkpoint.frame));
    w.pod(checkpoint.runHash);
    w.pod(checkpoint.time);
    w.array(checkpoint.velocity.data(), std::size_t(checkpoint.velocity.size()));
    w.array(checkpoint.magnetic.data(), std::size_t(checkpoint.magnetic.size()));
    const StepCarry& carry = checkpoint.carry;
    w.array(carry.heldRate.data(), std::size_t(carry.heldRate.size()));
    w.pod(std::uint64_t(carry.warmRhs.size()));
    for (const Eigen::VectorXd& r : carry.warmRhs) w.array(r.data(), std::size_t(r.size()));
    w.pod(std::uint32_t(carry.substeps));
    w.pod(std::uint32_t(carry.easySteps));
    w.vector(checkpoint.smoke.density);
    w.vector(checkpoint.smoke.temperature);
    w.vector(checkpoint.smoke.fuel);
    w.vector(checkpoint.smoke.flame);
    w.vector(checkpoint.particles.position);
    w.vector(checkpoint.particles.velocity);
    w.vector(checkpoint.particles.set);
    ByteWriter checksum;
    checksum.pod(checksum64(w.bytes()));
    writeFileAtomically(path, {w.bytes(), checksum.bytes()}, "checkpoint");
}

Checkpoint readCheckpoint(const std::filesystem::path& path) {
    const std::string bytes = readCheckpointBytes(path);
    const std::string_view body(bytes.data(), bytes.size() - sizeof(std::uint64_t));
    std::uint64_t checksum;
    std::memcpy(&checksum, bytes.data() + body.size(), sizeof checksum);
    if (checksum != checksum64(body)) fail(path, "checksum mismatch (damaged)");

    ByteReader reader(body, [&](std::string_view why) { return refusal(path, why); });
    reader.skip(sizeof kMagic + sizeof kVersion);  // checked by readCheckpointBytes
    Checkpoint checkpoint;
    const auto frame = reader.pod<std::uint32_t>();
    if (frame > std::uint32_t(std::numeric_limits<int>::max()))
        fail(path, "its frame number is out of range");
    checkpoint.frame = int(frame);
    checkpoint.runHash = reader.pod<std::uint64_t>();
    checkpoint.time = reader.pod<double>();
    if (!(std::isfinite(checkpoint.time) && checkpoint.time >= 0.0))
        fail(path, "its time is not a non-negative number");
    checkpoint.velocity = modalVector(reader);
    checkpoint.magnetic = modalVector(reader);
    StepCarry& carry = checkpoint.carry;
    carry.heldRate = modalVector(reader);
    if (carry.heldRate.size() != 0 && carry.heldRate.size() != checkpoint.velocity.size())
        fail(path, "its held rate and velocity sizes differ");
    const auto warm = reader.pod<std::uint64_t>();
    if (warm > kMaxWarmRhs) fail(path, "its warm start holds more than two right-hand sides");
    for (std::uint64_t i = 0; i < warm; ++i) {
        carry.warmRhs.push_back(modalVector(reader));
        if (carry.warmRhs.back().size() != checkpoint.velocity.size() + checkpoint.magnetic.size())
            fail(path, "its warm start and state sizes differ");
    }
    const auto substeps = reader.pod<std::uint32_t>(), easy = reader.pod<std::uint32_t>();
    if (substeps < 1 || substeps > kMaxSubsteps || easy > kMaxSubsteps * 1000u)
        fail(path, "its substep count is out of range");
    carry.substeps = int(substeps);
    carry.easySteps = int(easy);
    // No step can continue from them; refused here, naming the file, not by the simulator.
    std::vector<std::pair<const Eigen::VectorXd*, std::string>> modal{
        {&checkpoint.velocity, "velocity"},
        {&checkpoint.magnetic, "magnetic field"},
        {&carry.heldRate, "held rate"}};
    for (const Eigen::VectorXd& r : carry.warmRhs) modal.emplace_back(&r, "warm start");
    for (const auto& [values, what] : modal)
        if (!values->allFinite()) fail(path, "its modal " + what + " is not finite");
    checkpoint.smoke.density = reader.vector<double>();
    checkpoint.smoke.temperature = reader.vector<double>();
    checkpoint.smoke.fuel = reader.vector<double>();
    checkpoint.smoke.flame = reader.vector<double>();
    if (checkpoint.smoke.density.size() != checkpoint.smoke.temperature.size())
        fail(path, "density and temperature sizes differ");
    if (checkpoint.smoke.fuel.size() != checkpoint.smoke.flame.size() ||
        (!checkpoint.smoke.fuel.empty() &&
         checkpoint.smoke.fuel.size() != checkpoint.smoke.density.size()))
        fail(path, "its fuel and flame do not hold a value per smoke cell");
    for (const auto& [field, what] :
         {std::pair{&checkpoint.smoke.density, "density"},
          std::pair{&checkpoint.smoke.temperature, "temperature"},
          std::pair{&checkpoint.smoke.fuel, "fuel"}, std::pair{&checkpoint.smoke.flame, "flame"}})
        if (!std::all_of(field->begin(), field->end(), [](double c) { return std::isfinite(c); }))
            fail(path, std::string("its smoke ") + what + " is not finite");
    Particles& particles = checkpoint.particles;
    particles.position = reader.vector<double>();
    particles.velocity = reader.vector<double>();
    particles.set = reader.vector<std::uint8_t>();
    try {
        requireParticleValues(particles);
    } catch (const Error& e) {
        fail(path, std::string("its ") + e.what());
    }
    if (!reader.atEnd()) fail(path, "bytes follow its particles");
    return checkpoint;
}

}  // namespace modeflow
