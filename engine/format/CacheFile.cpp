#include "engine/format/CacheFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <new>
#include <string>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "engine/core/InputFile.h"
#include "engine/format/CacheConsistency.h"

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W', '-', 'B', 'A', 'S', 'I', 'S', 0, 0};
constexpr size_t kHeaderSize = 16 + 4 + 4 + 8 + 8;
/// The largest cache file read (64 GiB): far above any basis a precompute finishes, low enough that
/// a damaged or hostile file cannot make the reader ask for terabytes.
constexpr std::uintmax_t kMaxCacheBytes = std::uintmax_t{1} << 36;

void putVector(ByteWriter& w, const Eigen::VectorXd& v) {
    w.array(v.data(), std::size_t(v.size()));
}

void putMatrix(ByteWriter& w, const Eigen::MatrixXd& m) {
    w.pod<std::uint64_t>(std::uint64_t(m.rows()));
    w.pod<std::uint64_t>(std::uint64_t(m.cols()));
    w.values(m.data(), std::size_t(m.size()));
}

/// The next `count` doubles into `to`, which may be null when count is 0 (an empty vector's
/// data()).
void takeDoubles(ByteReader& r, double* to, std::size_t count) {
    const std::string_view bytes = r.bytes(count * sizeof(double));
    if (count != 0) std::memcpy(to, bytes.data(), bytes.size());
}

Eigen::VectorXd takeVector(ByteReader& r) {
    const auto n = r.count(sizeof(double));
    Eigen::VectorXd v(static_cast<Eigen::Index>(n));
    takeDoubles(r, v.data(), n);
    return v;
}

Eigen::MatrixXd takeMatrix(ByteReader& r) {
    const auto rows = r.pod<std::uint64_t>();
    const auto cols = r.pod<std::uint64_t>();
    // An empty matrix keeps its other dimension (no scalar modes: cells × 0), which only a
    // bound far beyond any grid limits.
    constexpr std::uint64_t kMaxDimension = std::uint64_t{1} << 40;
    if (rows > kMaxDimension || cols > kMaxDimension ||
        (cols != 0 && rows > r.remaining() / sizeof(double) / cols))
        r.fail("a matrix runs past the end");
    Eigen::MatrixXd m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    takeDoubles(r, m.data(), rows * cols);
    return m;
}

std::string serialize(const BasisCache& c) {
    ByteWriter w;
    w.string(c.key);
    w.pod<std::int32_t>(c.grid.dim);
    for (int r : c.grid.resolution) w.pod<std::int32_t>(r);
    for (double x : c.grid.boundsMin) w.pod(x);
    for (double x : c.grid.boundsMax) w.pod(x);
    for (bool periodic : c.grid.periodic) w.pod<std::uint8_t>(periodic);
    w.pod<std::int32_t>(int(c.wall));
    w.pod<std::int32_t>(int(c.boundary));
    w.vector(c.cellFraction);
    w.vector(c.faces);
    putVector(w, c.faceStar);
    w.vector(c.cells);
    putVector(w, c.cellStar);
    putVector(w, c.velocity.eigenvalues);
    putMatrix(w, c.velocity.modes);
    w.vector(c.velocity.modeNumbers);
    w.pod<std::int32_t>(c.velocity.harmonic);
    w.pod(c.velocity.penalty);
    w.pod<std::int32_t>(int(c.scalar.boundary));
    w.vector(c.scalar.cells);
    putVector(w, c.scalar.cellStar);
    putVector(w, c.scalar.eigenvalues);
    putMatrix(w, c.scalar.modes);
    w.pod<std::int32_t>(c.scalar.omittedConstants);
    w.pod<std::int32_t>(int(c.coefficients.storage));
    w.vector(c.coefficients.packed);
    w.vector(c.coefficients.k);
    w.vector(c.coefficients.i);
    w.vector(c.coefficients.j);
    w.vector(c.coefficients.value);
    w.pod(c.coefficients.density);
    w.pod<std::uint64_t>(c.timings.size());
    for (const auto& [name, seconds] : c.timings) {
        w.string(name);
        w.pod(seconds);
    }
    return w.bytes();
}

BasisCache deserialize(std::string_view payload, const std::string& where) {
    ByteReader r(payload, [&](std::string_view why) {
        return where + " is corrupt (" + std::string(why) +
               "); delete it or rerun precompute with --force";
    });
    BasisCache c;
    c.key = r.string();
    c.grid.dim = r.pod<std::int32_t>();
    for (int& x : c.grid.resolution) x = r.pod<std::int32_t>();
    for (double& x : c.grid.boundsMin) x = r.pod<double>();
    for (double& x : c.grid.boundsMax) x = r.pod<double>();
    for (bool& periodic : c.grid.periodic) periodic = r.pod<std::uint8_t>() != 0;
    c.wall = WallKind(r.pod<std::int32_t>());
    c.boundary = BoundaryTreatment(r.pod<std::int32_t>());
    c.cellFraction = r.vector<double>();
    c.faces = r.vector<std::int64_t>();
    c.faceStar = takeVector(r);
    c.cells = r.vector<std::int64_t>();
    c.cellStar = takeVector(r);
    c.velocity.eigenvalues = takeVector(r);
    c.velocity.modes = takeMatrix(r);
    c.velocity.modeNumbers = r.vector<int>();
    c.velocity.harmonic = r.pod<std::int32_t>();
    c.velocity.penalty = r.pod<double>();
    c.scalar.boundary = ScalarBoundary(r.pod<std::int32_t>());
    c.scalar.cells = r.vector<std::int64_t>();
    c.scalar.cellStar = takeVector(r);
    c.scalar.eigenvalues = takeVector(r);
    c.scalar.modes = takeMatrix(r);
    c.scalar.omittedConstants = r.pod<std::int32_t>();
    c.coefficients.storage = BasisCache::Coefficients::Storage(r.pod<std::int32_t>());
    c.coefficients.packed = r.vector<double>();
    c.coefficients.k = r.vector<std::int32_t>();
    c.coefficients.i = r.vector<std::int32_t>();
    c.coefficients.j = r.vector<std::int32_t>();
    c.coefficients.value = r.vector<double>();
    c.coefficients.density = r.pod<double>();
    const auto timings = r.pod<std::uint64_t>();
    for (std::uint64_t i = 0; i < timings && !r.atEnd(); ++i) {
        std::string name = r.string();
        c.timings.emplace_back(std::move(name), r.pod<double>());
    }
    if (!r.atEnd()) r.fail("bytes follow its last record");
    requireConsistentCache(c, where);
    return c;
}

struct Header {
    std::uint64_t keyHash = 0;
    std::uint64_t payloadSize = 0;
};

Header parseHeader(std::string_view bytes, const std::string& where) {
    if (!hasCacheMagic(bytes)) throw Error(where + " is not a modeflow basis cache (bad magic)");
    ByteReader r(bytes,
                 [&](std::string_view) { return where + " is truncated (incomplete header)"; });
    r.bytes(sizeof kMagic);
    const auto version = r.pod<std::uint32_t>();
    if (version != kCacheFormatVersion)
        throw Error(where + " has format version " + std::to_string(version) +
                    ", this modeflow reads version " + std::to_string(kCacheFormatVersion) +
                    "; rerun precompute to rebuild it");
    r.pod<std::uint32_t>();  // reserved
    Header h;
    h.keyHash = r.pod<std::uint64_t>();
    h.payloadSize = r.pod<std::uint64_t>();
    return h;
}

/// An open cache file and its size, after the checks of inputFileSize.
struct OpenCache {
    std::string where;
    std::ifstream in;
    std::uintmax_t size = 0;
};

OpenCache openCache(const std::filesystem::path& path) {
    OpenCache file;
    file.where = "cache file " + path.string();
    file.size = inputFileSize(path, "cache file", kMaxCacheBytes);
    file.in.open(path, std::ios::binary);
    if (!file.in)
        throw Error(path.string() + ": cannot open the cache file (" + std::strerror(errno) + ")");
    return file;
}

/// The header, read alone: a file that is no cache is refused before its bulk is read.
Header readHeader(OpenCache& file) {
    std::string header(kHeaderSize, '\0');
    file.in.read(header.data(), std::streamsize(kHeaderSize));
    header.resize(size_t(file.in.gcount()));
    return parseHeader(header, file.where);
}

}  // namespace

void writeCache(const std::filesystem::path& path, const BasisCache& cache) {
    const std::string payload = serialize(cache);
    ByteWriter header;
    header.pod(kMagic);
    header.pod(kCacheFormatVersion);
    header.pod<std::uint32_t>(0);
    header.pod(fnv1a64(cache.key));
    header.pod<std::uint64_t>(payload.size());
    ByteWriter checksum;
    checksum.pod(fnv1a64(payload));
    writeFileAtomically(path, {header.bytes(), payload, checksum.bytes()}, "cache file");
}

BasisCache readCache(const std::filesystem::path& path) {
    OpenCache file = openCache(path);
    const Header h = readHeader(file);
    const std::string& where = file.where;
    if (h.payloadSize > file.size)
        throw Error(where + " is truncated (" + std::to_string(file.size) +
                    " bytes, its header declares a payload of " + std::to_string(h.payloadSize) +
                    ")");
    if (file.size != kHeaderSize + h.payloadSize + 8)
        throw Error(where + " is truncated or has trailing bytes (" + std::to_string(file.size) +
                    " bytes, expected " + std::to_string(kHeaderSize + h.payloadSize + 8) + ")");
    std::string payload;
    try {
        payload.resize(size_t(h.payloadSize));
    } catch (const std::bad_alloc&) {
        throw Error("not enough memory to read " + where + " (" + std::to_string(file.size) +
                    " bytes)");
    }
    std::uint64_t checksum = 0;
    file.in.read(payload.data(), std::streamsize(payload.size()));
    file.in.read(reinterpret_cast<char*>(&checksum), sizeof checksum);
    if (!file.in)
        throw Error(where + " could not be read to its end (it changed while it was read?)");
    if (checksum != fnv1a64(payload)) throw Error(where + " is corrupt (checksum mismatch)");
    BasisCache c = deserialize(payload, where);
    if (fnv1a64(c.key) != h.keyHash)
        throw Error(where + " is corrupt (key does not match its hash)");
    return c;
}

bool hasCacheMagic(std::string_view bytes) {
    return bytes.size() >= sizeof(kMagic) && std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) == 0;
}

std::uint64_t readCacheKeyHash(const std::filesystem::path& path) {
    OpenCache file = openCache(path);
    return readHeader(file).keyHash;
}

}  // namespace modeflow
