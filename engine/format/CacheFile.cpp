#include "engine/format/CacheFile.h"

#include <cerrno>
#include <cstring>
#include <deque>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "engine/core/InputFile.h"
#include "engine/format/CacheConsistency.h"

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W',
                             '-', 'B', 'A', 'S', 'I', 'S', 0,   0};
constexpr size_t kHeaderSize = 16 + 4 + 4 + 8 + 8;
/// The largest cache file read (64 GiB): far above any basis a precompute finishes, low enough that
/// a damaged or hostile file cannot make the reader ask for terabytes.
constexpr std::uintmax_t kMaxCacheBytes = std::uintmax_t{1} << 36;

void putVector(ByteWriter& w, const Eigen::VectorXd& v) {
    w.array(v.data(), std::size_t(v.size()));
}

/// Field by field (no padding bytes in the file): waves, shifts, amplitudes.
void putSeparable(ByteWriter& w, const std::vector<SeparableMode>& modes) {
    w.pod<std::uint64_t>(modes.size());
    for (const SeparableMode& m : modes) {
        for (std::int32_t l : m.wave) w.pod(l);
        for (std::uint8_t s : m.shift) w.pod(s);
        for (double a : m.amplitude) w.pod(a);
    }
}

std::vector<SeparableMode> takeSeparable(ByteReader& r) {
    constexpr std::size_t kBytes =
        3 * (sizeof(std::int32_t) + sizeof(std::uint8_t) + sizeof(double));
    std::vector<SeparableMode> modes(r.count(kBytes));
    for (SeparableMode& m : modes) {
        for (std::int32_t& l : m.wave) l = r.pod<std::int32_t>();
        for (std::uint8_t& s : m.shift) s = r.pod<std::uint8_t>();
        for (double& a : m.amplitude) a = r.pod<double>();
    }
    return modes;
}

Eigen::VectorXd takeVector(ByteReader& r) {
    const auto n = r.count(sizeof(double));
    Eigen::VectorXd v(static_cast<Eigen::Index>(n));
    r.read(v.data(), n * sizeof(double));
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
    r.read(m.data(), rows * cols * sizeof(double));
    return m;
}

/// The payload as pieces to write one after another: the small records serialized, the large
/// arrays (columns, coefficients) viewed where they lie, so that a cache of gigabytes (closed-form
/// coefficients at N = 10 000) is never copied to be written.
class Payload {
public:
    ByteWriter& small() { return mSmall.back(); }
    /// A count and the values, viewed in place.
    template <typename T>
    void array(const T* values, std::size_t count) {
        small().pod<std::uint64_t>(count);
        view(values, count);
    }
    template <typename T>
    void view(const T* values, std::size_t count) {
        mViews.push_back({reinterpret_cast<const char*>(values), count * sizeof(T)});
        mOrder.push_back(false);
        mSmall.emplace_back();
        mOrder.push_back(true);
    }
    /// The pieces in order.
    std::vector<std::string_view> pieces() const {
        std::vector<std::string_view> out;
        std::size_t small = 0, view = 0;
        out.push_back(mSmall[small++].bytes());
        for (std::size_t p = 0; p < mOrder.size(); ++p)
            out.push_back(mOrder[p] ? std::string_view(mSmall[small++].bytes()) : mViews[view++]);
        return out;
    }

private:
    std::deque<ByteWriter> mSmall = std::deque<ByteWriter>(1);
    std::vector<std::string_view> mViews;
    std::vector<bool> mOrder;  ///< after the first small piece: true small, false view
};

void putRows(Payload& p, const SparseRows& m) {
    p.array(m.start.data(), m.start.size());
    p.array(m.column.data(), m.column.size());
    p.array(m.value.data(), m.value.size());
}

SparseRows takeRows(ByteReader& r) {
    SparseRows m;
    m.start = r.vector<std::int64_t>();
    m.column = r.vector<std::int32_t>();
    m.value = r.vector<double>();
    return m;
}

/// Rows, columns, then the values viewed in place.
void putMatrix(Payload& p, const Eigen::MatrixXd& m) {
    p.small().pod<std::uint64_t>(std::uint64_t(m.rows()));
    p.small().pod<std::uint64_t>(std::uint64_t(m.cols()));
    p.view(m.data(), std::size_t(m.size()));
}

/// A surface basis's mesh, edges and runtime matrices, as flat arrays of coordinates and indices.
void putSurface(Payload& p, const BasisCache::Surface& s) {
    std::vector<double> points;
    for (const Vec3& v : s.mesh.vertices) points.insert(points.end(), v.begin(), v.end());
    std::vector<std::int32_t> corners;
    for (const auto& t : s.mesh.triangles) corners.insert(corners.end(), t.begin(), t.end());
    std::vector<std::int32_t> ends;
    for (const auto& e : s.edges) ends.insert(ends.end(), e.begin(), e.end());
    p.small().vector(points);
    p.small().vector(corners);
    p.small().vector(ends);
    putMatrix(p, s.advection);
    putMatrix(p, s.vertexVelocity);
}

void serialize(const BasisCache& c, Payload& p) {
    p.small().string(c.key);
    p.small().pod<std::int32_t>(c.grid.dim);
    for (int r : c.grid.resolution) p.small().pod<std::int32_t>(r);
    for (double x : c.grid.boundsMin) p.small().pod(x);
    for (double x : c.grid.boundsMax) p.small().pod(x);
    for (bool periodic : c.grid.periodic) p.small().pod<std::uint8_t>(periodic);
    for (bool open : c.grid.open) p.small().pod<std::uint8_t>(open);
    p.small().pod<std::int32_t>(int(c.wall));
    p.small().pod<std::int32_t>(int(c.boundary));
    p.array(c.cellFraction.data(), c.cellFraction.size());
    p.array(c.faces.data(), c.faces.size());
    p.array(c.faceStar.data(), std::size_t(c.faceStar.size()));
    p.array(c.cells.data(), c.cells.size());
    p.array(c.cellStar.data(), std::size_t(c.cellStar.size()));
    p.small().pod<std::int32_t>(int(c.velocity.source));
    putVector(p.small(), c.velocity.eigenvalues);
    putMatrix(p, c.velocity.modes);
    putSeparable(p.small(), c.velocity.separable);
    p.small().vector(c.velocity.modeNumbers);
    p.small().pod<std::int32_t>(c.velocity.harmonic);
    p.small().pod(c.velocity.penalty);
    p.small().pod<std::int32_t>(int(c.scalar.boundary));
    p.array(c.scalar.cells.data(), c.scalar.cells.size());
    p.array(c.scalar.cellStar.data(), std::size_t(c.scalar.cellStar.size()));
    p.small().pod<std::int32_t>(int(c.scalar.source));
    putVector(p.small(), c.scalar.eigenvalues);
    putMatrix(p, c.scalar.modes);
    putSeparable(p.small(), c.scalar.separable);
    p.small().pod<std::int32_t>(c.scalar.omittedConstants);
    putRows(p, c.quadrature.curl);
    putRows(p, c.quadrature.velocityB);
    putRows(p, c.quadrature.velocityC);
    p.small().pod<std::uint64_t>(c.windBase.size());
    for (const std::vector<double>& flow : c.windBase) p.array(flow.data(), flow.size());
    p.small().pod<std::uint64_t>(c.windStokes.size());
    for (const std::vector<double>& modes : c.windStokes) p.array(modes.data(), modes.size());
    p.small().pod<std::int32_t>(int(c.coefficients.storage));
    p.array(c.coefficients.packed.data(), c.coefficients.packed.size());
    p.array(c.coefficients.k.data(), c.coefficients.k.size());
    p.array(c.coefficients.i.data(), c.coefficients.i.size());
    p.array(c.coefficients.j.data(), c.coefficients.j.size());
    p.array(c.coefficients.value.data(), c.coefficients.value.size());
    p.small().pod(c.coefficients.density);
    p.small().pod<std::uint64_t>(c.timings.size());
    for (const auto& [name, seconds] : c.timings) {
        p.small().string(name);
        p.small().pod(seconds);
    }
    p.small().pod<std::int32_t>(int(c.kind));
    if (c.kind == BasisKind::Surface) putSurface(p, c.surface);
}

BasisSource takeSource(ByteReader& r) {
    const auto value = r.pod<std::int32_t>();
    if (value != int(BasisSource::Eigensolve) && value != int(BasisSource::ClosedForm))
        r.fail("a basis source is out of range");
    return BasisSource(value);
}

/// The mesh and edges of a surface basis; whether their indices and sizes fit the rest is
/// requireConsistentCache's to check.
void takeSurface(ByteReader& r, BasisCache::Surface& s) {
    const std::vector<double> points = r.vector<double>();
    const std::vector<std::int32_t> corners = r.vector<std::int32_t>();
    const std::vector<std::int32_t> ends = r.vector<std::int32_t>();
    s.advection = takeMatrix(r);
    s.vertexVelocity = takeMatrix(r);
    if (points.size() % 3 != 0 || corners.size() % 3 != 0 || ends.size() % 2 != 0)
        r.fail("its surface's points, triangles or edges are not whole");
    for (std::size_t i = 0; i < points.size(); i += 3)
        s.mesh.vertices.push_back({points[i], points[i + 1], points[i + 2]});
    for (std::size_t i = 0; i < corners.size(); i += 3)
        s.mesh.triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
    for (std::size_t i = 0; i < ends.size(); i += 2) s.edges.push_back({ends[i], ends[i + 1]});
}

/// The records of a payload, in the order serialize writes them; whether they fit together is
/// requireConsistentCache's to check, once the checksum has been.
BasisCache deserialize(ByteReader& r) {
    BasisCache c;
    c.key = r.string();
    c.grid.dim = r.pod<std::int32_t>();
    for (int& x : c.grid.resolution) x = r.pod<std::int32_t>();
    for (double& x : c.grid.boundsMin) x = r.pod<double>();
    for (double& x : c.grid.boundsMax) x = r.pod<double>();
    for (bool& periodic : c.grid.periodic) periodic = r.pod<std::uint8_t>() != 0;
    for (bool& open : c.grid.open) open = r.pod<std::uint8_t>() != 0;
    c.wall = WallKind(r.pod<std::int32_t>());
    c.boundary = BoundaryTreatment(r.pod<std::int32_t>());
    c.cellFraction = r.vector<double>();
    c.faces = r.vector<std::int64_t>();
    c.faceStar = takeVector(r);
    c.cells = r.vector<std::int64_t>();
    c.cellStar = takeVector(r);
    c.velocity.source = takeSource(r);
    c.velocity.eigenvalues = takeVector(r);
    c.velocity.modes = takeMatrix(r);
    c.velocity.separable = takeSeparable(r);
    c.velocity.modeNumbers = r.vector<int>();
    c.velocity.harmonic = r.pod<std::int32_t>();
    c.velocity.penalty = r.pod<double>();
    c.scalar.boundary = ScalarBoundary(r.pod<std::int32_t>());
    c.scalar.cells = r.vector<std::int64_t>();
    c.scalar.cellStar = takeVector(r);
    c.scalar.source = takeSource(r);
    c.scalar.eigenvalues = takeVector(r);
    c.scalar.modes = takeMatrix(r);
    c.scalar.separable = takeSeparable(r);
    c.scalar.omittedConstants = r.pod<std::int32_t>();
    c.quadrature.curl = takeRows(r);
    c.quadrature.velocityB = takeRows(r);
    c.quadrature.velocityC = takeRows(r);
    const auto windFlows = r.pod<std::uint64_t>();
    if (windFlows > 6) r.fail("it holds wind base flows for more than three axes");
    for (std::uint64_t a = 0; a < windFlows; ++a) c.windBase.push_back(r.vector<double>());
    const auto windCorrections = r.pod<std::uint64_t>();
    if (windCorrections > 6) r.fail("it holds Stokes corrections for more than three axes");
    for (std::uint64_t a = 0; a < windCorrections; ++a) c.windStokes.push_back(r.vector<double>());
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
    const auto kind = r.pod<std::int32_t>();
    if (kind != int(BasisKind::Grid) && kind != int(BasisKind::Surface))
        r.fail("its basis kind is out of range");
    c.kind = BasisKind(kind);
    if (c.kind == BasisKind::Surface) takeSurface(r, c.surface);
    if (!r.atEnd()) r.fail("bytes follow its last record");
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
    r.skip(sizeof kMagic);
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
    Payload payload;
    serialize(cache, payload);
    const std::vector<std::string_view> pieces = payload.pieces();
    std::uint64_t size = 0;
    Checksum hash;
    for (const std::string_view piece : pieces) {
        size += piece.size();
        hash.update(piece);
    }
    ByteWriter header;
    header.pod(kMagic);
    header.pod(kCacheFormatVersion);
    header.pod<std::uint32_t>(0);
    header.pod(fnv1a64(cache.key));
    header.pod<std::uint64_t>(size);
    ByteWriter checksum;
    checksum.pod(hash.value());
    std::vector<std::string_view> file{header.bytes()};
    file.insert(file.end(), pieces.begin(), pieces.end());
    file.push_back(checksum.bytes());
    writeFileAtomically(path, file, "cache file");
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
    // Decoded as it is read (a cache of gigabytes is never held twice); the checksum is compared
    // before anything decoded is trusted.
    ByteReader r(file.in, h.payloadSize, [&](std::string_view why) {
        return where + " is corrupt (" + std::string(why) +
               "); delete it or rerun precompute with --force";
    });
    BasisCache c;
    try {
        c = deserialize(r);
    } catch (const std::bad_alloc&) {
        throw Error("not enough memory to read " + where + " (" + std::to_string(file.size) +
                    " bytes)");
    }
    std::uint64_t checksum = 0;
    if (!file.in.read(reinterpret_cast<char*>(&checksum), sizeof checksum))
        throw Error(where + " could not be read to its end (it changed while it was read?)");
    if (checksum != r.hash()) throw Error(where + " is corrupt (checksum mismatch)");
    requireConsistentCache(c, where);
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
