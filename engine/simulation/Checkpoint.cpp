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

#include "engine/core/AtomicFile.h"
#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"
#include "engine/core/InputFile.h"

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W',
                             '-', 'R', 'E', 'S', 'U', 'M', 'E', '\0'};
/// 2: the magnetic field after the velocity; 3: XXH3; 4: the held rate after the field.
constexpr std::uint32_t kVersion = 4;
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
    w.array(checkpoint.heldRate.data(), std::size_t(checkpoint.heldRate.size()));
    w.vector(checkpoint.smoke.density);
    w.vector(checkpoint.smoke.temperature);
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
    checkpoint.heldRate = modalVector(reader);
    if (checkpoint.heldRate.size() != 0 && checkpoint.heldRate.size() != checkpoint.velocity.size())
        fail(path, "its held rate and velocity sizes differ");
    // No step can continue from them; refused here, naming the file, not by the simulator.
    for (const auto& [values, what] : {std::pair{&checkpoint.velocity, "velocity"},
                                       std::pair{&checkpoint.magnetic, "magnetic field"},
                                       std::pair{&checkpoint.heldRate, "held rate"}})
        if (!values->allFinite()) fail(path, std::string("its modal ") + what + " is not finite");
    checkpoint.smoke.density = reader.vector<double>();
    checkpoint.smoke.temperature = reader.vector<double>();
    if (checkpoint.smoke.density.size() != checkpoint.smoke.temperature.size())
        fail(path, "density and temperature sizes differ");
    if (!reader.atEnd()) fail(path, "bytes follow its smoke fields");
    return checkpoint;
}

}  // namespace modeflow
