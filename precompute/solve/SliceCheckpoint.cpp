#include "precompute/solve/SliceCheckpoint.h"

#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <system_error>

#include "engine/core/AtomicFile.h"
#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W',
                             '-', 'S', 'L', 'I', 'C', 'E', 0,   0};
constexpr std::uint32_t kVersion = 2;  ///< 2: XXH3 checksum
constexpr const char* kExtension = ".mfslice";

template <typename T>
std::string_view bytesOf(const T* values, std::size_t count) {
    return {reinterpret_cast<const char*>(values), count * sizeof(T)};
}

/// "abcd.mfbasis" → "abcd.": what every checkpoint name of that cache begins with.
std::string namePrefix(const fs::path& cachePath) {
    return cachePath.stem().string() + ".";
}

}  // namespace

std::uint64_t sliceProblemHash(const Eigen::SparseMatrix<double>& stiffness,
                               const Eigen::VectorXd& massDiagonal, const EigenRequest& request) {
    ByteWriter w;
    w.string("sliced eigenproblem");
    w.pod(std::int64_t(stiffness.rows()));
    w.pod(std::int64_t(request.count));
    w.pod(request.shift);
    w.pod(request.estimate);
    w.pod(request.tolerance);
    w.pod(std::int32_t(request.spectralDimension));
    Checksum hash;
    hash.update(w.bytes());
    for (Eigen::Index c = 0; c < stiffness.outerSize(); ++c) {
        const auto begin = std::size_t(stiffness.outerIndexPtr()[c]);
        const auto n = std::size_t(stiffness.isCompressed() ? stiffness.outerIndexPtr()[c + 1] -
                                                                  stiffness.outerIndexPtr()[c]
                                                            : stiffness.innerNonZeroPtr()[c]);
        hash.update(bytesOf(stiffness.innerIndexPtr() + begin, n));
        hash.update(bytesOf(stiffness.valuePtr() + begin, n));
    }
    hash.update(bytesOf(massDiagonal.data(), std::size_t(massDiagonal.size())));
    return hash.value();
}

fs::path sliceCheckpointPath(const fs::path& cachePath, std::uint64_t problem, int interval) {
    std::ostringstream name;
    name << namePrefix(cachePath) << std::hex << std::setw(16) << std::setfill('0') << problem
         << std::dec << "." << interval << kExtension;
    return cachePath.parent_path() / name.str();
}

void writeSliceCheckpoint(const fs::path& path, const SliceCheckpoint& checkpoint) {
    ByteWriter w;
    w.pod(kMagic);
    w.pod(kVersion);
    w.pod(checkpoint.problem);
    w.pod(std::int32_t(checkpoint.interval));
    w.pod(checkpoint.lo);
    w.pod(checkpoint.hi);
    w.pod(std::uint64_t(checkpoint.vectors.rows()));
    w.pod(std::uint64_t(checkpoint.values.size()));
    // The eigenpairs are written from where they are, not copied into one string first.
    const std::string_view values =
        bytesOf(checkpoint.values.data(), std::size_t(checkpoint.values.size()));
    const std::string_view vectors =
        bytesOf(checkpoint.vectors.data(), std::size_t(checkpoint.vectors.size()));
    Checksum hash;
    for (const std::string_view piece : {std::string_view(w.bytes()), values, vectors})
        hash.update(piece);
    const std::uint64_t checksum = hash.value();
    writeFileAtomically(path, {w.bytes(), values, vectors, bytesOf(&checksum, 1)},
                        "eigensolver checkpoint");
}

SliceCheckpoint readSliceCheckpoint(const fs::path& path, std::uint64_t problem, int interval,
                                    double lo, Eigen::Index rows) {
    const std::string where = "eigensolver checkpoint " + path.string();
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (ec || !in) throw Error(where + " cannot be read");
    ByteReader r(in, size, [&](std::string_view why) { return where + " is " + std::string(why); });
    char magic[sizeof kMagic];
    r.read(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof kMagic) != 0)
        r.fail("not an eigensolver checkpoint (bad magic)");
    if (r.pod<std::uint32_t>() != kVersion) r.fail("of another format version");
    SliceCheckpoint c;
    c.problem = r.pod<std::uint64_t>();
    c.interval = r.pod<std::int32_t>();
    c.lo = r.pod<double>();
    c.hi = r.pod<double>();
    const auto storedRows = r.pod<std::uint64_t>();
    const auto count = r.pod<std::uint64_t>();
    if (c.problem != problem || c.interval != interval || storedRows != std::uint64_t(rows))
        r.fail("of another eigenproblem or interval");
    if (std::memcmp(&c.lo, &lo, sizeof lo) != 0 || !(c.hi > c.lo))
        r.fail("of another interval of the spectrum");
    // Checked before anything is allocated: the pairs and the checksum are all that is left.
    const std::uint64_t doubles = r.remaining() / sizeof(double);
    if (count > doubles / (storedRows + 1) ||
        r.remaining() != (count * (storedRows + 1) + 1) * sizeof(double))
        r.fail("truncated or corrupt (its size does not match its eigenpair count)");
    c.values.resize(Eigen::Index(count));
    c.vectors.resize(rows, Eigen::Index(count));
    r.read(c.values.data(), std::size_t(c.values.size()) * sizeof(double));
    r.read(c.vectors.data(), std::size_t(c.vectors.size()) * sizeof(double));
    const std::uint64_t body = r.hash();
    if (r.pod<std::uint64_t>() != body) r.fail("damaged (checksum mismatch)");
    return c;
}

int removeSliceCheckpoints(const fs::path& cachePath) {
    const std::string prefix = namePrefix(cachePath);
    const fs::path folder = cachePath.has_parent_path() ? cachePath.parent_path() : ".";
    std::error_code ec, unremovable;
    int removed = 0;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.starts_with(prefix) && it->path().extension() == kExtension &&
            fs::remove(it->path(), unremovable))
            ++removed;
    }
    return removed;
}

}  // namespace modeflow
