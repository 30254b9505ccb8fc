#include "engine/format/CacheFile.h"

#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the cache format is little-endian");

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W', '-', 'B', 'A', 'S', 'I', 'S', 0, 0};
constexpr size_t kHeaderSize = 16 + 4 + 4 + 8 + 8;

class Writer {
public:
    template <typename T>
    void pod(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        mBytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
    }
    void string(std::string_view s) {
        pod<std::uint64_t>(s.size());
        mBytes.append(s);
    }
    template <typename T>
    void vector(const std::vector<T>& v) {
        pod<std::uint64_t>(v.size());
        mBytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    void vector(const Eigen::VectorXd& v) {
        pod<std::uint64_t>(std::uint64_t(v.size()));
        mBytes.append(reinterpret_cast<const char*>(v.data()), size_t(v.size()) * sizeof(double));
    }
    void matrix(const Eigen::MatrixXd& m) {
        pod<std::uint64_t>(std::uint64_t(m.rows()));
        pod<std::uint64_t>(std::uint64_t(m.cols()));
        mBytes.append(reinterpret_cast<const char*>(m.data()), size_t(m.size()) * sizeof(double));
    }
    const std::string& bytes() const { return mBytes; }

private:
    std::string mBytes;
};

class Reader {
public:
    Reader(std::string_view bytes, const std::filesystem::path& path) : mBytes(bytes), mPath(path) {}

    template <typename T>
    T pod() {
        T v;
        std::memcpy(&v, take(sizeof(T)), sizeof(T));
        return v;
    }
    std::string string() {
        const auto n = count(1);
        return std::string(take(n), n);
    }
    template <typename T>
    std::vector<T> vector() {
        const auto n = count(sizeof(T));
        std::vector<T> v(n);
        std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
        return v;
    }
    Eigen::VectorXd eigenVector() {
        const auto n = count(sizeof(double));
        Eigen::VectorXd v(static_cast<Eigen::Index>(n));
        std::memcpy(v.data(), take(n * sizeof(double)), n * sizeof(double));
        return v;
    }
    Eigen::MatrixXd matrix() {
        const auto rows = pod<std::uint64_t>();
        const auto cols = pod<std::uint64_t>();
        if (cols != 0 && rows > (mBytes.size() - mAt) / sizeof(double) / cols) corrupt();
        Eigen::MatrixXd m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
        std::memcpy(m.data(), take(rows * cols * sizeof(double)), rows * cols * sizeof(double));
        return m;
    }
    bool atEnd() const { return mAt == mBytes.size(); }
    [[noreturn]] void corrupt() const {
        throw Error("cache file " + mPath.string() +
                    " is corrupt (its contents do not match its layout); delete it or rerun "
                    "precompute with --force");
    }

private:
    std::uint64_t count(size_t elementSize) {
        const auto n = pod<std::uint64_t>();
        if (n > (mBytes.size() - mAt) / elementSize) corrupt();
        return n;
    }
    const char* take(size_t n) {
        if (n > mBytes.size() - mAt) corrupt();
        const char* p = mBytes.data() + mAt;
        mAt += n;
        return p;
    }
    std::string_view mBytes;
    size_t mAt = 0;
    const std::filesystem::path& mPath;
};

std::string serialize(const BasisCache& c) {
    Writer w;
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
    w.vector(c.faceStar);
    w.vector(c.cells);
    w.vector(c.cellStar);
    w.vector(c.velocity.eigenvalues);
    w.matrix(c.velocity.modes);
    w.vector(c.velocity.modeNumbers);
    w.pod<std::int32_t>(c.velocity.harmonic);
    w.pod(c.velocity.penalty);
    w.pod<std::int32_t>(int(c.scalar.boundary));
    w.vector(c.scalar.cells);
    w.vector(c.scalar.cellStar);
    w.vector(c.scalar.eigenvalues);
    w.matrix(c.scalar.modes);
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
    w.pod<std::int32_t>(int(c.kind));
    if (c.kind == BasisKind::Surface) {
        std::vector<double> points;
        for (const Vec3& p : c.surface.mesh.vertices) points.insert(points.end(), p.begin(), p.end());
        std::vector<std::int32_t> corners;
        for (const auto& t : c.surface.mesh.triangles) corners.insert(corners.end(), t.begin(), t.end());
        std::vector<std::int32_t> ends;
        for (const auto& e : c.surface.edges) ends.insert(ends.end(), e.begin(), e.end());
        w.vector(points);
        w.vector(corners);
        w.vector(ends);
        w.matrix(c.surface.advection);
        w.matrix(c.surface.vertexVelocity);
    }
    return w.bytes();
}

/// The mesh and edges of a surface basis, refused unless every index and size fits the rest.
void readSurface(Reader& r, BasisCache& c) {
    const std::vector<double> points = r.vector<double>();
    const std::vector<std::int32_t> corners = r.vector<std::int32_t>();
    const std::vector<std::int32_t> ends = r.vector<std::int32_t>();
    c.surface.advection = r.matrix();
    c.surface.vertexVelocity = r.matrix();
    if (points.size() % 3 != 0 || corners.size() % 3 != 0 || ends.size() % 2 != 0) r.corrupt();
    const auto vertices = std::int64_t(points.size() / 3);
    for (const std::int32_t v : corners)
        if (v < 0 || v >= vertices) r.corrupt();
    for (const std::int32_t v : ends)
        if (v < 0 || v >= vertices) r.corrupt();
    for (std::size_t i = 0; i < points.size(); i += 3)
        c.surface.mesh.vertices.push_back({points[i], points[i + 1], points[i + 2]});
    for (std::size_t i = 0; i < corners.size(); i += 3)
        c.surface.mesh.triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
    for (std::size_t i = 0; i < ends.size(); i += 2) c.surface.edges.push_back({ends[i], ends[i + 1]});
    const auto edges = Eigen::Index(c.surface.edges.size());
    if (c.faceStar.size() != edges || c.velocity.modes.rows() != edges ||
        c.cellStar.size() != Eigen::Index(c.surface.mesh.triangles.size()) ||
        c.scalar.cellStar.size() != vertices || c.scalar.modes.rows() != vertices ||
        c.surface.advection.rows() != Eigen::Index(pairCount(std::size_t(c.scalar.modes.cols()))) ||
        c.surface.advection.cols() != c.velocity.modes.cols() || c.surface.vertexVelocity.rows() != 3 * vertices ||
        c.surface.vertexVelocity.cols() != c.velocity.modes.cols())
        r.corrupt();
}

BasisCache deserialize(std::string_view payload, const std::filesystem::path& path) {
    Reader r(payload, path);
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
    c.faceStar = r.eigenVector();
    c.cells = r.vector<std::int64_t>();
    c.cellStar = r.eigenVector();
    c.velocity.eigenvalues = r.eigenVector();
    c.velocity.modes = r.matrix();
    c.velocity.modeNumbers = r.vector<int>();
    c.velocity.harmonic = r.pod<std::int32_t>();
    c.velocity.penalty = r.pod<double>();
    c.scalar.boundary = ScalarBoundary(r.pod<std::int32_t>());
    c.scalar.cells = r.vector<std::int64_t>();
    c.scalar.cellStar = r.eigenVector();
    c.scalar.eigenvalues = r.eigenVector();
    c.scalar.modes = r.matrix();
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
    const auto kind = r.pod<std::int32_t>();
    if (kind != int(BasisKind::Grid) && kind != int(BasisKind::Surface)) r.corrupt();
    c.kind = BasisKind(kind);
    if (c.kind == BasisKind::Surface) readSurface(r, c);
    if (!r.atEnd()) r.corrupt();
    return c;
}

std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open cache file " + path.string() + ": " +
                         std::error_code(errno, std::generic_category()).message());
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Header {
    std::uint64_t keyHash = 0;
    std::uint64_t payloadSize = 0;
};

Header parseHeader(std::string_view bytes, const std::filesystem::path& path) {
    const std::string where = "cache file " + path.string();
    if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        throw Error(where + " is not a modeflow basis cache (bad magic)");
    if (bytes.size() < kHeaderSize) throw Error(where + " is truncated (incomplete header)");
    std::uint32_t version;
    std::memcpy(&version, bytes.data() + 16, 4);
    if (version != kCacheFormatVersion)
        throw Error(where + " has format version " + std::to_string(version) +
                    ", this modeflow reads version " + std::to_string(kCacheFormatVersion) +
                    "; rerun precompute to rebuild it");
    Header h;
    std::memcpy(&h.keyHash, bytes.data() + 24, 8);
    std::memcpy(&h.payloadSize, bytes.data() + 32, 8);
    return h;
}

}  // namespace

void writeCache(const std::filesystem::path& path, const BasisCache& cache) {
    const std::string payload = serialize(cache);
    Writer w;
    w.pod(kMagic);
    w.pod(kCacheFormatVersion);
    w.pod<std::uint32_t>(0);
    w.pod(fnv1a64(cache.key));
    w.pod<std::uint64_t>(payload.size());
    const std::uint64_t checksum = fnv1a64(payload);

    const std::filesystem::path tmp =
        path.parent_path() / (path.filename().string() + ".tmp." + std::to_string(::getpid()));
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot write cache file " + tmp.string() + ": " +
                              std::error_code(errno, std::generic_category()).message());
        out.write(w.bytes().data(), std::streamsize(w.bytes().size()));
        out.write(payload.data(), std::streamsize(payload.size()));
        out.write(reinterpret_cast<const char*>(&checksum), sizeof(checksum));
        out.flush();
        if (!out) {
            out.close();
            std::filesystem::remove(tmp);
            throw Error("writing cache file " + tmp.string() + " failed (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp);
        throw Error("cannot move cache file into place at " + path.string() + ": " + ec.message());
    }
}

BasisCache readCache(const std::filesystem::path& path) {
    const std::string bytes = readAll(path);
    const Header h = parseHeader(bytes, path);
    if (bytes.size() != kHeaderSize + h.payloadSize + 8)
        throw Error("cache file " + path.string() + " is truncated or has trailing bytes (" +
                    std::to_string(bytes.size()) + " bytes, expected " +
                    std::to_string(kHeaderSize + h.payloadSize + 8) + ")");
    const std::string_view payload(bytes.data() + kHeaderSize, h.payloadSize);
    std::uint64_t checksum;
    std::memcpy(&checksum, bytes.data() + kHeaderSize + h.payloadSize, 8);
    if (checksum != fnv1a64(payload))
        throw Error("cache file " + path.string() + " is corrupt (checksum mismatch)");
    BasisCache c = deserialize(payload, path);
    if (fnv1a64(c.key) != h.keyHash)
        throw Error("cache file " + path.string() + " is corrupt (key does not match its hash)");
    return c;
}

std::uint64_t readCacheKeyHash(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open cache file " + path.string());
    std::string header(kHeaderSize, '\0');
    in.read(header.data(), std::streamsize(kHeaderSize));
    header.resize(size_t(in.gcount()));
    return parseHeader(header, path).keyHash;
}

}  // namespace modeflow
