#include "engine/simulation/Checkpoint.h"

#include <array>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

#include "engine/format/CacheFile.h"
#include "engine/core/Error.h"

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

/// Reads values front to back, failing with the file's name on a short read.
class Reader {
public:
    Reader(const std::string& bytes, const std::filesystem::path& path) : mBytes(bytes), mPath(path) {}
    template <typename T>
    T get() {
        T value;
        take(&value, sizeof(T));
        return value;
    }
    std::vector<double> doubles() {
        const auto count = get<std::uint64_t>();
        if (count > (mBytes.size() - mAt) / sizeof(double)) fail("truncated");
        std::vector<double> values(count);
        take(values.data(), count * sizeof(double));
        return values;
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error("checkpoint " + mPath.string() + ": " + why + "; delete it to start the run afresh");
    }

private:
    void take(void* to, std::size_t bytes) {
        if (bytes > mBytes.size() - mAt) fail("truncated");
        std::memcpy(to, mBytes.data() + mAt, bytes);
        mAt += bytes;
    }
    const std::string& mBytes;
    const std::filesystem::path& mPath;
    std::size_t mAt = 0;
};

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
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw Error("cannot write checkpoint " + path.string() + " (disk full or not writable)");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw Error("cannot write checkpoint " + path.string() + ": " + error.message());
    }
}

Checkpoint readCheckpoint(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("checkpoint " + path.string() + ": cannot be opened");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Reader reader(bytes, path);
    if (bytes.size() < sizeof kMagic + sizeof(std::uint64_t) || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        reader.fail("not a modeflow checkpoint");
    const std::size_t body = bytes.size() - sizeof(std::uint64_t);
    std::uint64_t checksum;
    std::memcpy(&checksum, bytes.data() + body, sizeof checksum);
    if (checksum != fnv1a64(std::string_view(bytes.data(), body))) reader.fail("checksum mismatch (damaged)");

    reader.get<std::array<char, sizeof kMagic>>();
    if (reader.get<std::uint32_t>() != kVersion) reader.fail("written by another modeflow version");
    Checkpoint checkpoint;
    checkpoint.frame = int(reader.get<std::uint32_t>());
    checkpoint.runHash = reader.get<std::uint64_t>();
    checkpoint.time = reader.get<double>();
    const auto modal = [&reader] {
        const std::vector<double> values = reader.doubles();
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size())));
    };
    checkpoint.velocity = modal();
    checkpoint.magnetic = modal();
    checkpoint.smoke.density = reader.doubles();
    checkpoint.smoke.temperature = reader.doubles();
    if (checkpoint.smoke.density.size() != checkpoint.smoke.temperature.size())
        reader.fail("density and temperature sizes differ");
    return checkpoint;
}

}  // namespace modeflow
