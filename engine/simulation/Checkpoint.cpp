#include "engine/simulation/Checkpoint.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>

#include "engine/format/CacheFile.h"
#include "engine/format/Error.h"
#include "engine/format/InputFile.h"

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W', '-', 'R', 'E', 'S', 'U', 'M', 'E', '\0'};
constexpr std::uint32_t kVersion = 2;  ///< 2: the magnetic field after the velocity

template <typename T>
void put(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

void putDoubles(std::string& out, const double* values, std::size_t count) {
    put(out, std::uint64_t(count));
    out.append(reinterpret_cast<const char*>(values), count * sizeof(double));
}

/// The largest checkpoint read (64 GiB): the modal state and two fields of the largest smoke grid a
/// scene may ask for fit, and a damaged file cannot make the reader ask for terabytes.
constexpr std::uintmax_t kMaxCheckpointBytes = std::uintmax_t{1} << 36;
/// Magic, version, frame, run hash, time: what is checked before the bulk is read.
constexpr std::size_t kHeaderBytes = sizeof kMagic + 4 + 4 + 8 + 8;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    throw Error("checkpoint " + path.string() + ": " + why + "; delete it to start the run afresh");
}

/// The C library's word for the call that just failed.
std::string systemCause() {
    return std::error_code(errno, std::generic_category()).message();
}

/// Reads values front to back, failing with the file's name on a short read.
class Reader {
public:
    Reader(std::string_view bytes, const std::filesystem::path& path)
        : mBytes(bytes), mPath(path) {}
    template <typename T>
    T get() {
        T value;
        take(&value, sizeof(T));
        return value;
    }
    std::vector<double> doubles() {
        const auto count = get<std::uint64_t>();
        if (count > (mBytes.size() - mAt) / sizeof(double)) fail(mPath, "truncated");
        std::vector<double> values(count);
        take(values.data(), count * sizeof(double));
        return values;
    }
    bool atEnd() const { return mAt == mBytes.size(); }

private:
    /// `to` may be null when `bytes` is 0 (an empty vector's data()).
    void take(void* to, std::size_t bytes) {
        if (bytes > mBytes.size() - mAt) fail(mPath, "truncated");
        if (bytes != 0) std::memcpy(to, mBytes.data() + mAt, bytes);
        mAt += bytes;
    }
    std::string_view mBytes;
    const std::filesystem::path& mPath;
    std::size_t mAt = 0;
};

/// The whole file, its header checked before the rest is read: a file that is no checkpoint is
/// refused without reading its bulk.
std::string readCheckpointBytes(const std::filesystem::path& path) {
    const std::uintmax_t size = regularFileSize(path, "checkpoint", kMaxCheckpointBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot be opened: " + systemCause());
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

}  // namespace

void writeCheckpoint(const std::filesystem::path& path, const Checkpoint& checkpoint) {
    std::string bytes(kMagic, sizeof kMagic);
    put(bytes, kVersion);
    put(bytes, std::uint32_t(checkpoint.frame));
    put(bytes, checkpoint.runHash);
    put(bytes, checkpoint.time);
    putDoubles(bytes, checkpoint.velocity.data(), std::size_t(checkpoint.velocity.size()));
    putDoubles(bytes, checkpoint.magnetic.data(), std::size_t(checkpoint.magnetic.size()));
    putDoubles(bytes, checkpoint.smoke.density.data(), checkpoint.smoke.density.size());
    putDoubles(bytes, checkpoint.smoke.temperature.data(), checkpoint.smoke.temperature.size());
    put(bytes, fnv1a64(bytes));

    const std::filesystem::path temporary = path.string() + ".tmp-" + std::to_string(::getpid());
    const auto failWriting = [&](const std::string& cause) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);  // never leave a partial checkpoint behind
        throw Error("cannot write checkpoint " + path.string() + ": " + cause);
    };
    {
        errno = 0;
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) failWriting("cannot create " + temporary.string() + ": " + systemCause());
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) failWriting(errno != 0 ? systemCause() : "input/output error");
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) failWriting("cannot rename " + temporary.string() + " over it: " + error.message());
}

Checkpoint readCheckpoint(const std::filesystem::path& path) {
    const std::string bytes = readCheckpointBytes(path);
    const std::size_t body = bytes.size() - sizeof(std::uint64_t);
    std::uint64_t checksum;
    std::memcpy(&checksum, bytes.data() + body, sizeof checksum);
    if (checksum != fnv1a64(std::string_view(bytes.data(), body)))
        fail(path, "checksum mismatch (damaged)");

    Reader reader(std::string_view(bytes.data(), body), path);
    reader.get<std::array<char, sizeof kMagic>>();
    reader.get<std::uint32_t>();  // the version, checked by readCheckpointBytes
    Checkpoint checkpoint;
    const std::uint32_t frame = reader.get<std::uint32_t>();
    if (frame > std::uint32_t(std::numeric_limits<int>::max()))
        fail(path, "its frame number is out of range");
    checkpoint.frame = int(frame);
    checkpoint.runHash = reader.get<std::uint64_t>();
    checkpoint.time = reader.get<double>();
    if (!(std::isfinite(checkpoint.time) && checkpoint.time >= 0.0))
        fail(path, "its time is not a non-negative number");
    const auto modal = [&reader] {
        const std::vector<double> values = reader.doubles();
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size())));
    };
    checkpoint.velocity = modal();
    checkpoint.magnetic = modal();
    checkpoint.smoke.density = reader.doubles();
    checkpoint.smoke.temperature = reader.doubles();
    if (checkpoint.smoke.density.size() != checkpoint.smoke.temperature.size())
        fail(path, "density and temperature sizes differ");
    if (!reader.atEnd()) fail(path, "bytes follow its smoke fields");
    return checkpoint;
}

}  // namespace modeflow
