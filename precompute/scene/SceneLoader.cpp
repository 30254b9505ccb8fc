/// @file SceneLoader.cpp
/// Scene file → SceneSpec. The only file that sees toml++: the rest of modeflow works on plain
/// values. Every table is checked for unknown keys before its values are read, so a typo is never
/// silently replaced by a default.

#include "precompute/scene/SceneLoader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>

#include <toml++/toml.h>

#include "engine/format/QuotedText.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

template <typename T>
using Choices = std::span<const std::pair<std::string_view, T>>;

constexpr std::pair<std::string_view, ShapeKind> kShapeKinds[] = {
    {"ball", ShapeKind::Ball},           {"box", ShapeKind::Box},
    {"ellipsoid", ShapeKind::Ellipsoid}, {"cylinder", ShapeKind::Cylinder},
    {"torus", ShapeKind::Torus},         {"mesh", ShapeKind::Mesh},
};
constexpr std::pair<std::string_view, CsgOp> kCsgOps[] = {
    {"union", CsgOp::Union}, {"subtract", CsgOp::Subtract}, {"intersect", CsgOp::Intersect}};
constexpr std::pair<std::string_view, ScalarBoundary> kScalarBoundaries[] = {
    {"neumann", ScalarBoundary::Neumann}, {"dirichlet", ScalarBoundary::Dirichlet}};
constexpr std::pair<std::string_view, WallKind> kWalls[] = {{"free-slip", WallKind::FreeSlip},
                                                            {"no-slip", WallKind::NoSlip}};
constexpr std::pair<std::string_view, BoundaryTreatment> kBoundaries[] = {
    {"cut-cell", BoundaryTreatment::CutCell}, {"staircase", BoundaryTreatment::Staircase}};
constexpr std::pair<std::string_view, Integrator> kIntegrators[] = {
    {"explicit", Integrator::Explicit},
    {"rk4", Integrator::Rk4},
    {"midpoint", Integrator::Midpoint},
    {"trapezoidal", Integrator::Trapezoidal}};
constexpr std::pair<std::string_view, InitialVelocity> kInitialVelocities[] = {
    {"zero", InitialVelocity::Zero},
    {"random", InitialVelocity::Random},
    {"modes", InitialVelocity::Modes},
    {"vortices", InitialVelocity::Vortices}};
constexpr std::pair<std::string_view, InitialMagnetic> kInitialMagnetics[] = {
    {"random", InitialMagnetic::Random}, {"uniform", InitialMagnetic::Uniform}};

template <typename T>
std::string_view keywordOf(Choices<T> choices, T value) {
    for (const auto& [name, v] : choices) {
        if (v == value) return name;
    }
    return "?";
}

constexpr std::string_view kTopLevelTables[] = {"grid",    "domain", "basis", "simulation",
                                                "initial", "source", "obstacle", "smoke", "output"};
constexpr std::string_view kGridKeys[] = {"resolution", "bounds_min", "bounds_max"};
constexpr std::string_view kBasisKeys[] = {
    "velocity_modes", "modes", "scalar_modes", "scalar_boundary", "wall", "boundary", "subsamples"};
constexpr std::string_view kSimulationKeys[] = {"dt",  "integrator",           "viscosity",      "alpha",
                                                "mhd", "magnetic_diffusivity", "basis_precision"};
constexpr std::string_view kInitialKeys[] = {
    "velocity", "energy",        "seed",     "band", "amplitudes", "vortex", "magnetic", "magnetic_energy",
    "magnetic_seed", "magnetic_direction", "magnetic_strength", "magnetic_wall_layer"};
/// [initial] keys of the magnetic field (MHD only), which go with any velocity choice.
constexpr std::string_view kInitialFieldKeys[] = {"magnetic",           "magnetic_energy",   "magnetic_seed",
                                                  "magnetic_direction", "magnetic_strength", "magnetic_wall_layer"};
constexpr std::string_view kVortexKeys2d[] = {"center", "strength", "radius"};
constexpr std::string_view kVortexKeys3d[] = {"center", "normal", "ring_radius", "radius",
                                              "strength"};

/// The `[initial]` keys each velocity choice reads besides `velocity`.
std::span<const std::string_view> initialKeys(InitialVelocity velocity) {
    static constexpr std::string_view random[] = {"energy", "seed", "band"};
    static constexpr std::string_view modes[] = {"amplitudes"};
    static constexpr std::string_view vortices[] = {"vortex", "energy"};
    switch (velocity) {
        case InitialVelocity::Zero:
            return {};
        case InitialVelocity::Random:
            return random;
        case InitialVelocity::Modes:
            return modes;
        case InitialVelocity::Vortices:
            return vortices;
    }
    return {};
}

/// The `[initial]` keys each magnetic field choice reads besides `magnetic`.
std::span<const std::string_view> magneticKeys(InitialMagnetic magnetic) {
    static constexpr std::string_view random[] = {"magnetic_energy", "magnetic_seed"};
    static constexpr std::string_view uniform[] = {"magnetic_direction", "magnetic_strength",
                                                   "magnetic_wall_layer"};
    return magnetic == InitialMagnetic::Uniform ? std::span<const std::string_view>(uniform)
                                                : std::span<const std::string_view>(random);
}
constexpr std::pair<std::string_view, ObstacleShape> kObstacleShapes[] = {
    {"ball", ObstacleShape::Ball}, {"box", ObstacleShape::Box}, {"capsule", ObstacleShape::Capsule}};
constexpr std::string_view kObstacleKeys[] = {"shape", "radius", "half_size", "axis", "path"};
constexpr std::string_view kSmokeKeys[] = {"buoyancy", "resolution_scale", "advection"};
constexpr std::pair<std::string_view, AdvectionScheme> kAdvectionSchemes[] = {
    {"maccormack", AdvectionScheme::MacCormack}, {"semi-lagrangian", AdvectionScheme::SemiLagrangian}};
constexpr std::pair<std::string_view, bool> kBasisPrecisions[] = {{"float32", false}, {"float16", true}};
constexpr std::string_view kOutputKeys[] = {"frames", "steps_per_frame"};
constexpr std::string_view kSourceExtraKeys[] = {"density", "temperature", "start", "end"};

/// The keys each shape takes besides `shape` (and `op` in `[[domain]]`).
std::span<const std::string_view> shapeKeys(ShapeKind kind) {
    static constexpr std::string_view ball[] = {"center", "radius"};
    static constexpr std::string_view box[] = {"min", "max"};
    static constexpr std::string_view ellipsoid[] = {"center", "radii"};
    static constexpr std::string_view cylinder[] = {"center", "radius", "half_height"};
    static constexpr std::string_view torus[] = {"center", "major_radius", "minor_radius"};
    static constexpr std::string_view mesh[] = {"file"};
    switch (kind) {
        case ShapeKind::Ball:
            return ball;
        case ShapeKind::Box:
            return box;
        case ShapeKind::Ellipsoid:
            return ellipsoid;
        case ShapeKind::Cylinder:
            return cylinder;
        case ShapeKind::Torus:
            return torus;
        case ShapeKind::Mesh:
            return mesh;
    }
    return {};
}

bool contains(std::span<const std::string_view> list, std::string_view item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

/// Optimal-string-alignment distance, case-insensitive: a swapped pair of letters counts once,
/// which is the most common typo ("grdi").
std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
    auto lower = [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
                lower(a[i - 2]) == lower(b[j - 1])) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}

/// The closest candidate, if it is close enough to be a plausible typo.
std::optional<std::string_view> closest(std::string_view word,
                                        std::span<const std::string_view> candidates) {
    const std::size_t allowed = word.size() <= 3 ? 1 : word.size() <= 6 ? 2 : word.size() / 3;
    std::optional<std::string_view> best;
    std::size_t bestDistance = allowed + 1;
    for (std::string_view c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

/// "a, b or c"
std::string joinWords(std::span<const std::string_view> words, std::string_view last = "or") {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) out += i + 1 == words.size() ? " " + std::string(last) + " " : ", ";
        out += words[i];
    }
    return out;
}

std::string formatNumber(double x) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return ec == std::errc{} ? std::string(buffer, end) : std::to_string(x);
}

const char* axisName(int axis) {
    static constexpr const char* names[] = {"x", "y", "z"};
    return names[axis];
}

std::string describeType(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a floating-point number (" + formatNumber(node.as_floating_point()->get()) +
                   ")";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        default:
            return "nothing";
    }
}

/// Mode-list parsing without a key prefix; returns the problem, or nothing when `out` is valid.
std::optional<std::string> parseModeList(std::string_view text, std::vector<ModeRange>& out) {
    auto isSpace = [](char c) { return c == ' ' || c == '\t'; };
    std::size_t pos = 0;
    auto skipSpace = [&] {
        while (pos < text.size() && isSpace(text[pos])) ++pos;
    };
    auto readNumber = [&](int& value) -> std::optional<std::string> {
        skipSpace();
        const char* begin = text.data() + pos;
        const char* end = text.data() + text.size();
        if (begin == end || !std::isdigit(static_cast<unsigned char>(*begin))) {
            return "expected a mode number at position " + std::to_string(pos + 1);
        }
        const auto [stop, ec] = std::from_chars(begin, end, value);
        if (ec == std::errc::result_out_of_range) {
            return "mode number at position " + std::to_string(pos + 1) + " is too large";
        }
        pos += static_cast<std::size_t>(stop - begin);
        skipSpace();
        return std::nullopt;
    };

    out.clear();
    skipSpace();
    if (pos == text.size()) return std::string("empty mode list");
    while (true) {
        ModeRange range;
        if (auto problem = readNumber(range.first)) return problem;
        range.last = range.first;
        if (pos < text.size() && text[pos] == '-') {
            ++pos;
            if (auto problem = readNumber(range.last)) return problem;
        }
        const std::string item =
            std::to_string(range.first) +
            (range.last != range.first ? "-" + std::to_string(range.last) : "");
        if (range.first < 1) return "modes are numbered from 1, got " + item;
        if (range.last < range.first) return "range " + item + " ends before it starts";
        if (!out.empty() && range.first <= out.back().last) {
            return "range " + item + " overlaps or comes before the previous one (" +
                   std::to_string(out.back().first) + "-" + std::to_string(out.back().last) +
                   "); ranges must be sorted and disjoint";
        }
        out.push_back(range);
        if (pos == text.size()) return std::nullopt;
        if (text[pos] != ',') {
            return std::string("unexpected character '") + text[pos] + "' at position " +
                   std::to_string(pos + 1) + " (expected ',' or '-')";
        }
        ++pos;
    }
}

/// A table and the name messages give it ("[grid]", "[[domain]] #2 (torus)").
struct Section {
    const toml::table& table;
    std::string name;
};

/// Lower/upper limits a number must respect.
enum class Sign { Any, NonNegative, Positive };

class SceneParser {
public:
    explicit SceneParser(const fs::path& origin) : mFile(origin.string()), mOrigin(origin) {}

    SceneSpec parse(std::string_view text) {
        const toml::table root = parseToml(text);
        SceneSpec scene;
        scene.sourceFile = mOrigin;
        scene.name = mOrigin.stem().string();

        checkTopLevel(root);
        const toml::table* grid = requireTable(root, "grid");
        scene.grid = readGrid({*grid, "[grid]"});

        forEachEntry(root, "domain", [&](const toml::table& t, int index) {
            scene.domain.push_back(readShape(t, "[[domain]]", index, true));
        });
        scene.basis = readBasis({*requireTable(root, "basis"), "[basis]"}, scene.grid);
        if (const toml::table* t = optionalTable(root, "simulation")) {
            scene.simulation = readSimulation({*t, "[simulation]"});
        }
        if (const toml::table* t = optionalTable(root, "initial")) {
            // Before reading them, so a field key in a non-MHD scene is named for that.
            for (std::string_view key : kInitialFieldKeys)
                if (!scene.simulation.mhd && t->contains(key))
                    fail(std::string("[initial].") + std::string(key),
                         "only used with [simulation] mhd = true", t->get(key));
            scene.initial = readInitial({*t, "[initial]"}, scene.basis);
        }
        forEachEntry(root, "source", [&](const toml::table& t, int index) {
            scene.sources.push_back(readSource(t, index));
        });
        forEachEntry(root, "obstacle", [&](const toml::table& t, int index) {
            scene.obstacles.push_back(readObstacle({t, "[[obstacle]] #" + std::to_string(index)}));
        });
        if (const toml::table* t = optionalTable(root, "smoke")) {
            scene.smoke = readSmoke({*t, "[smoke]"}, scene.grid);
        }
        if (const toml::table* t = optionalTable(root, "output")) {
            scene.output = readOutput({*t, "[output]"});
        }
        return scene;
    }

private:
    std::string mFile;
    fs::path mOrigin;
    int mDim = 2;

    // ---- messages -------------------------------------------------------------------------

    [[noreturn]] void fail(std::string_view where, std::string_view what,
                           const toml::node* at = nullptr) const {
        std::string message = mFile + ": " + std::string(where) + ": " + std::string(what);
        if (at != nullptr && at->source().begin.line > 0) {
            message += " (line " + std::to_string(at->source().begin.line) + ")";
        }
        throw Error(message);
    }

    [[noreturn]] void fail(const Section& s, std::string_view key, std::string_view what,
                           const toml::node* at = nullptr) const {
        fail(s.name + "." + std::string(key), what, at != nullptr ? at : &s.table);
    }

    // ---- structure ------------------------------------------------------------------------

    toml::table parseToml(std::string_view text) const {
#if TOML_EXCEPTIONS
        try {
            return toml::parse(text, mFile);
        } catch (const toml::parse_error& e) {
            throwSyntaxError(e);
        }
#else
        toml::parse_result result = toml::parse(text, mFile);
        if (!result) throwSyntaxError(result.error());
        return std::move(result).table();
#endif
    }

    [[noreturn]] void throwSyntaxError(const toml::parse_error& e) const {
        const auto& begin = e.source().begin;
        throw Error(mFile + ": line " + std::to_string(begin.line) + ", column " +
                    std::to_string(begin.column) +
                    ": TOML syntax error: " + std::string(e.description()));
    }

    void checkTopLevel(const toml::table& root) const {
        for (const auto& [key, node] : root) {
            const std::string_view name = key.str();
            if (contains(kTopLevelTables, name)) continue;
            std::string what =
                node.is_table() || node.is_array_of_tables() ? "unknown table" : "unknown key";
            if (auto guess = closest(name, kTopLevelTables)) {
                what += " (did you mean " + std::string(*guess) + "?)";
            } else {
                what += " (a scene holds " + joinWords(kTopLevelTables, "and") + ")";
            }
            fail(std::string(name), what, &node);
        }
    }

    const toml::table* optionalTable(const toml::table& root, std::string_view name) const {
        const toml::node* node = root.get(name);
        if (node == nullptr) return nullptr;
        if (!node->is_table()) {
            fail("[" + std::string(name) + "]", "expected a table, got " + describeType(*node),
                 node);
        }
        return node->as_table();
    }

    const toml::table* requireTable(const toml::table& root, std::string_view name) const {
        const toml::table* table = optionalTable(root, name);
        if (table == nullptr) {
            fail("[" + std::string(name) + "]", "missing required table");
        }
        return table;
    }

    /// Calls `read(table, 1-based index)` for each `[[name]]` entry.
    template <typename Read>
    void forEachEntry(const toml::table& root, std::string_view name, Read&& read) const {
        const toml::node* node = root.get(name);
        if (node == nullptr) return;
        const std::string where = "[[" + std::string(name) + "]]";
        const toml::array* array = node->as_array();
        if (array == nullptr) {
            fail(where,
                 "expected an array of tables (write [[" + std::string(name) + "]], not [" +
                     std::string(name) + "]), got " + describeType(*node),
                 node);
        }
        int index = 0;
        for (const toml::node& entry : *array) {
            ++index;
            if (!entry.is_table()) {
                fail(where + " #" + std::to_string(index),
                     "expected a table, got " + describeType(entry), &entry);
            }
            read(*entry.as_table(), index);
        }
    }

    /// Rejects every key of `s` not in `allowed`, suggesting the nearest allowed one.
    void checkKeys(const Section& s, std::span<const std::string_view> allowed) const {
        for (const auto& [key, node] : s.table) {
            const std::string_view name = key.str();
            if (contains(allowed, name)) continue;
            std::string what = "unknown key";
            if (auto guess = closest(name, allowed)) {
                what += " (did you mean " + std::string(*guess) + "?)";
            } else {
                what += " (expected " + joinWords(allowed) + ")";
            }
            fail(s, name, what, &node);
        }
    }

    // ---- scalar values --------------------------------------------------------------------

    std::optional<double> number(const Section& s, std::string_view key) const {
        const toml::node* node = s.table.get(key);
        if (node == nullptr) return std::nullopt;
        return numberValue(*node, s.name + "." + std::string(key));
    }

    /// A float, or an integer standing for one (`radius = 1`).
    double numberValue(const toml::node& node, const std::string& where) const {
        double value = 0.0;
        if (const auto* i = node.as_integer()) {
            value = static_cast<double>(i->get());
        } else if (const auto* f = node.as_floating_point()) {
            value = f->get();
        } else {
            fail(where, "expected a number, got " + describeType(node), &node);
        }
        if (!std::isfinite(value)) fail(where, "must be finite, got " + formatNumber(value), &node);
        return value;
    }

    double readNumber(const Section& s, std::string_view key, double fallback,
                      Sign sign = Sign::Any) const {
        const std::optional<double> value = number(s, key);
        if (!value) return fallback;
        if (sign == Sign::Positive && !(*value > 0.0)) {
            fail(s, key, "must be > 0, got " + formatNumber(*value), s.table.get(key));
        }
        if (sign == Sign::NonNegative && *value < 0.0) {
            fail(s, key, "must be >= 0, got " + formatNumber(*value), s.table.get(key));
        }
        return *value;
    }

    double requireNumber(const Section& s, std::string_view key, Sign sign) const {
        if (!s.table.contains(key)) fail(s, key, "missing required key");
        return readNumber(s, key, 0.0, sign);
    }

    std::int64_t integerValue(const toml::node& node, const std::string& where) const {
        const auto* i = node.as_integer();
        if (i == nullptr) fail(where, "expected an integer, got " + describeType(node), &node);
        return i->get();
    }

    std::optional<std::int64_t> integer(const Section& s, std::string_view key, std::int64_t lo,
                                        std::int64_t hi) const {
        const toml::node* node = s.table.get(key);
        if (node == nullptr) return std::nullopt;
        const std::int64_t value = integerValue(*node, s.name + "." + std::string(key));
        if (value < lo || value > hi) {
            // Limits that only guard against overflow are not worth mentioning unless hit.
            const bool openEnded = hi == std::numeric_limits<std::int64_t>::max() ||
                                   hi == std::numeric_limits<int>::max();
            std::string what =
                !openEnded ? "must be between " + std::to_string(lo) + " and " + std::to_string(hi)
                : value < lo ? "must be at least " + std::to_string(lo)
                             : "is too large (at most " + std::to_string(hi) + ")";
            fail(s, key, what + ", got " + std::to_string(value), node);
        }
        return value;
    }

    int readInt(const Section& s, std::string_view key, int fallback, int lo,
                int hi = std::numeric_limits<int>::max()) const {
        const auto value = integer(s, key, lo, hi);
        return value ? static_cast<int>(*value) : fallback;
    }

    std::optional<std::string> string(const Section& s, std::string_view key) const {
        const toml::node* node = s.table.get(key);
        if (node == nullptr) return std::nullopt;
        const auto* str = node->as_string();
        if (str == nullptr) fail(s, key, "expected a string, got " + describeType(*node), node);
        return str->get();
    }

    template <typename T>
    T readChoice(const Section& s, std::string_view key, T fallback, Choices<T> choices) const {
        const std::optional<std::string> value = string(s, key);
        if (!value) return fallback;
        std::vector<std::string_view> names;
        for (const auto& [name, v] : choices) {
            if (name == *value) return v;
            names.push_back(name);
        }
        std::string what = "unknown value \"" + *value + "\"";
        if (auto guess = closest(*value, names))
            what += " (did you mean " + std::string(*guess) + "?)";
        fail(s, key, what + "; expected " + joinWords(names), s.table.get(key));
    }

    /// A point or extent with the scene's dimension; 2D leaves the third entry at 0.
    std::optional<Vec3> vector(const Section& s, std::string_view key) const {
        const toml::node* node = s.table.get(key);
        if (node == nullptr) return std::nullopt;
        const std::string where = s.name + "." + std::string(key);
        const toml::array* array = node->as_array();
        const std::string expected =
            std::to_string(mDim) + " numbers (the scene is " + std::to_string(mDim) + "D)";
        if (array == nullptr) {
            fail(where, "expected an array of " + expected + ", got " + describeType(*node), node);
        }
        if (array->size() != static_cast<std::size_t>(mDim)) {
            fail(where,
                 "expected " + expected + ", got " + std::to_string(array->size()) +
                     (array->size() == 1 ? " entry" : " entries"),
                 node);
        }
        Vec3 out{0.0, 0.0, 0.0};
        for (int a = 0; a < mDim; ++a) {
            out[a] = numberValue((*array)[a], where + "[" + std::to_string(a) + "]");
        }
        return out;
    }

    Vec3 requireVector(const Section& s, std::string_view key) const {
        const std::optional<Vec3> v = vector(s, key);
        if (!v) fail(s, key, "missing required key");
        return *v;
    }

    // ---- tables ---------------------------------------------------------------------------

    GridSpec readGrid(const Section& s) {
        checkKeys(s, kGridKeys);
        GridSpec grid;
        const toml::node* node = s.table.get("resolution");
        if (node == nullptr) fail(s, "resolution", "missing required key");
        const toml::array* array = node->as_array();
        if (array == nullptr) {
            fail(s, "resolution",
                 "expected an array of 2 or 3 integers, got " + describeType(*node), node);
        }
        if (array->size() != 2 && array->size() != 3) {
            fail(s, "resolution",
                 "expected 2 or 3 integers, got " + std::to_string(array->size()) +
                     (array->size() == 1 ? " entry" : " entries"),
                 node);
        }
        grid.dim = static_cast<int>(array->size());
        std::int64_t cells = 1;
        for (int a = 0; a < grid.dim; ++a) {
            const std::string where = s.name + ".resolution[" + std::to_string(a) + "]";
            const std::int64_t n = integerValue((*array)[a], where);
            if (n < 2 || n > kMaxGridResolution) {
                fail(where,
                     "must be between 2 and " + std::to_string(kMaxGridResolution) + ", got " +
                         std::to_string(n),
                     &(*array)[a]);
            }
            grid.resolution[a] = static_cast<int>(n);
            cells *= n;  // at most 4096^3 = 2^36: no overflow
        }
        if (cells > kMaxGridCells) {
            std::string dims;
            for (int a = 0; a < grid.dim; ++a) {
                dims += (a > 0 ? " x " : "") + std::to_string(grid.resolution[a]);
            }
            fail(s, "resolution",
                 dims + " = " + std::to_string(cells) +
                     " cells is absurdly large (the limit is 134217728 = 2^27 cells)",
                 node);
        }

        mDim = grid.dim;  // every vector from here on has the grid's dimension
        const Vec3 lo = requireVector(s, "bounds_min");
        const Vec3 hi = requireVector(s, "bounds_max");
        for (int a = 0; a < grid.dim; ++a) {
            if (!(hi[a] > lo[a])) {
                fail(s, "bounds_max",
                     std::string("must exceed bounds_min on every axis, but on axis ") +
                         axisName(a) + " bounds_min = " + formatNumber(lo[a]) +
                         " and bounds_max = " + formatNumber(hi[a]) + " (inverted bounds)",
                     s.table.get("bounds_max"));
            }
            grid.boundsMin[a] = lo[a];
            grid.boundsMax[a] = hi[a];
        }
        return grid;
    }

    ShapeSpec readShape(const toml::table& table, const std::string& section, int index,
                        bool isDomain) const {
        const std::string entry = section + " #" + std::to_string(index);
        const toml::node* shapeNode = table.get("shape");
        if (shapeNode == nullptr) {
            fail(entry + ".shape",
                 "missing required key (one of " +
                     std::string(isDomain ? "ball, box, ellipsoid, cylinder, "
                                            "torus or mesh"
                                          : "ball or box") +
                     ")",
                 &table);
        }
        ShapeSpec shape;
        shape.kind = readChoice(Section{table, entry}, "shape", ShapeKind::Ball,
                                Choices<ShapeKind>(kShapeKinds));
        const std::string_view kindName = keywordOf(Choices<ShapeKind>(kShapeKinds), shape.kind);
        const Section s{table, entry + " (" + std::string(kindName) + ")"};

        if (!isDomain && shape.kind != ShapeKind::Ball && shape.kind != ShapeKind::Box) {
            fail(s, "shape", "a source must be a ball or a box, got " + std::string(kindName),
                 shapeNode);
        }
        if (mDim == 2 && (shape.kind == ShapeKind::Cylinder || shape.kind == ShapeKind::Torus ||
                          shape.kind == ShapeKind::Mesh)) {
            fail(s, "shape",
                 "a " + std::string(kindName) +
                     " is 3D only, but this scene is 2D ([grid].resolution has 2 entries)",
                 shapeNode);
        }

        // Keys: the shape's own, plus `shape`, `op` (domain) or density/temperature (source).
        std::vector<std::string_view> allowed{"shape"};
        if (isDomain) allowed.push_back("op");
        if (!isDomain)
            allowed.insert(allowed.end(), std::begin(kSourceExtraKeys), std::end(kSourceExtraKeys));
        const auto own = shapeKeys(shape.kind);
        allowed.insert(allowed.end(), own.begin(), own.end());
        for (const auto& [key, node] : table) {
            const std::string_view name = key.str();
            if (contains(allowed, name)) continue;
            bool otherShapesKey = false;
            for (const auto& entry : kShapeKinds) {
                otherShapesKey = otherShapesKey || contains(shapeKeys(entry.second), name);
            }
            if (otherShapesKey) {
                fail(s, name,
                     "not a key of a " + std::string(kindName) + " (it takes " +
                         joinWords(own, "and") + ")",
                     &node);
            }
            if (!isDomain && name == "op") {
                fail(s, name, "unknown key (sources are not combined: op belongs to [[domain]])",
                     &node);
            }
            std::string what = "unknown key";
            if (auto guess = closest(name, allowed)) {
                what += " (did you mean " + std::string(*guess) + "?)";
            } else {
                what += " (expected " + joinWords(allowed) + ")";
            }
            fail(s, name, what, &node);
        }

        switch (shape.kind) {
            case ShapeKind::Ball:
                shape.center = requireVector(s, "center");
                shape.radius = requireNumber(s, "radius", Sign::Positive);
                break;
            case ShapeKind::Box: {
                shape.min = requireVector(s, "min");
                shape.max = requireVector(s, "max");
                for (int a = 0; a < mDim; ++a) {
                    if (!(shape.max[a] > shape.min[a])) {
                        fail(s, "max",
                             std::string("must exceed min on every axis, but on axis ") +
                                 axisName(a) + " min = " + formatNumber(shape.min[a]) +
                                 " and max = " + formatNumber(shape.max[a]),
                             table.get("max"));
                    }
                }
                break;
            }
            case ShapeKind::Ellipsoid:
                shape.center = requireVector(s, "center");
                shape.radii = requireVector(s, "radii");
                for (int a = 0; a < mDim; ++a) {
                    if (!(shape.radii[a] > 0.0)) {
                        fail(s, "radii",
                             std::string("must be > 0 on every axis, got ") +
                                 formatNumber(shape.radii[a]) + " on axis " + axisName(a),
                             table.get("radii"));
                    }
                }
                break;
            case ShapeKind::Cylinder:
                shape.center = requireVector(s, "center");
                shape.radius = requireNumber(s, "radius", Sign::Positive);
                shape.halfHeight = requireNumber(s, "half_height", Sign::Positive);
                break;
            case ShapeKind::Torus:
                shape.center = requireVector(s, "center");
                shape.majorRadius = requireNumber(s, "major_radius", Sign::Positive);
                shape.minorRadius = requireNumber(s, "minor_radius", Sign::Positive);
                if (!(shape.minorRadius < shape.majorRadius)) {
                    fail(s, "minor_radius",
                         "must be less than major_radius (" + formatNumber(shape.majorRadius) +
                             "), got " + formatNumber(shape.minorRadius),
                         table.get("minor_radius"));
                }
                break;
            case ShapeKind::Mesh:
                shape.meshFile = readMeshFile(s);
                break;
        }

        if (isDomain) {
            shape.op = readChoice(s, "op", CsgOp::Union, Choices<CsgOp>(kCsgOps));
            // The first shape starts the domain; subtracting from or intersecting with nothing
            // is almost surely a forgotten first entry, not an intent.
            if (index == 1 && shape.op != CsgOp::Union) {
                fail(s, "op",
                     "the first [[domain]] entry starts the domain, so it cannot " +
                         std::string(keywordOf(Choices<CsgOp>(kCsgOps), shape.op)) +
                         "; put the shape to " +
                         std::string(keywordOf(Choices<CsgOp>(kCsgOps), shape.op)) +
                         " from first (e.g. a box covering the grid)",
                     table.get("op"));
            }
        }
        return shape;
    }

    fs::path readMeshFile(const Section& s) const {
        const std::optional<std::string> file = string(s, "file");
        if (!file) fail(s, "file", "missing required key");
        if (file->empty()) fail(s, "file", "must name an OBJ file, got an empty string");
        fs::path path(*file);
        if (path.is_relative()) path = mOrigin.parent_path() / path;
        path = path.lexically_normal();
        std::string extension = path.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (extension != ".obj") {
            fail(s, "file", "only OBJ meshes are supported, got \"" + *file + "\"",
                 s.table.get("file"));
        }
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) {
            fail(s, "file", "no such file: " + path.string(), s.table.get("file"));
        }
        return path;
    }

    BasisSpec readBasis(const Section& s, const GridSpec& grid) const {
        checkKeys(s, kBasisKeys);
        BasisSpec basis;
        const toml::node* countNode = s.table.get("velocity_modes");
        const toml::node* listNode = s.table.get("modes");
        if (countNode != nullptr && listNode != nullptr) {
            fail(s, "modes", "give either velocity_modes or modes, not both", listNode);
        }
        if (countNode == nullptr && listNode == nullptr) {
            fail(s.name, "missing velocity_modes (a count, e.g. 40) or modes (e.g. \"1-115\")",
                 &s.table);
        }
        if (countNode != nullptr) {
            const int n = readInt(s, "velocity_modes", 1, 1);
            basis.velocityModes = {ModeRange{1, n}};
        } else {
            const std::string text = *string(s, "modes");
            if (auto problem = parseModeList(text, basis.velocityModes)) {
                fail(s, "modes", "bad mode list \"" + text + "\": " + *problem, listNode);
            }
        }

        // A cheap upper bound on the discrete spaces: more faces (cells) than modes asked for,
        // whatever the domain. The exact count is known only after the geometry is built.
        std::int64_t cells = 1;
        for (int a = 0; a < grid.dim; ++a) cells *= grid.resolution[a];
        std::int64_t faces = 0;
        for (int a = 0; a < grid.dim; ++a)
            faces += cells / grid.resolution[a] * (grid.resolution[a] + 1);
        if (basis.highestVelocityMode() > faces) {
            fail(s, countNode != nullptr ? "velocity_modes" : "modes",
                 "mode " + std::to_string(basis.highestVelocityMode()) +
                     " is beyond the discrete space: the grid has only " + std::to_string(faces) +
                     " faces",
                 countNode != nullptr ? countNode : listNode);
        }

        basis.scalarModes = readInt(s, "scalar_modes", 0, 0);
        if (basis.scalarModes > cells) {
            fail(s, "scalar_modes",
                 std::to_string(basis.scalarModes) +
                     " is beyond the discrete space: the grid has only " + std::to_string(cells) +
                     " cells",
                 s.table.get("scalar_modes"));
        }
        basis.scalarBoundary = readChoice(s, "scalar_boundary", ScalarBoundary::Neumann,
                                          Choices<ScalarBoundary>(kScalarBoundaries));
        basis.wall = readChoice(s, "wall", WallKind::FreeSlip, Choices<WallKind>(kWalls));
        basis.boundary = readChoice(s, "boundary", BoundaryTreatment::CutCell,
                                    Choices<BoundaryTreatment>(kBoundaries));
        basis.subsamples = readInt(s, "subsamples", 4, 1, 16);
        return basis;
    }

    SimulationSpec readSimulation(const Section& s) const {
        checkKeys(s, kSimulationKeys);
        SimulationSpec sim;
        sim.dt = readNumber(s, "dt", sim.dt, Sign::Positive);
        sim.integrator =
            readChoice(s, "integrator", sim.integrator, Choices<Integrator>(kIntegrators));
        sim.viscosity = readNumber(s, "viscosity", sim.viscosity, Sign::NonNegative);
        sim.alpha = readNumber(s, "alpha", sim.alpha, Sign::NonNegative);
        sim.halfPrecisionBasis =
            readChoice(s, "basis_precision", sim.halfPrecisionBasis, Choices<bool>(kBasisPrecisions));
        if (const toml::node* node = s.table.get("mhd")) {
            const auto* flag = node->as_boolean();
            if (flag == nullptr)
                fail(s, "mhd", "expected true or false, got " + describeType(*node), node);
            sim.mhd = flag->get();
        }
        sim.magneticDiffusivity =
            readNumber(s, "magnetic_diffusivity", sim.magneticDiffusivity, Sign::NonNegative);
        if (sim.mhd && sim.alpha > 0.0)
            fail(s, "alpha", "LANS-alpha and MHD cannot be combined (set one of them)",
                 s.table.get("alpha"));
        if (!sim.mhd && s.table.contains("magnetic_diffusivity"))
            fail(s, "magnetic_diffusivity", "only used with mhd = true",
                 s.table.get("magnetic_diffusivity"));
        return sim;
    }

    InitialSpec readInitial(const Section& s, const BasisSpec& basis) const {
        checkKeys(s, kInitialKeys);
        InitialSpec initial;
        initial.velocity = readChoice(s, "velocity", initial.velocity,
                                      Choices<InitialVelocity>(kInitialVelocities));
        // A key of another choice would be silently ignored, which hides a mistaken choice.
        const std::string chosen(keywordOf(Choices<InitialVelocity>(kInitialVelocities),
                                           initial.velocity));
        const auto own = initialKeys(initial.velocity);
        for (const auto& [key, node] : s.table) {
            const std::string_view name = key.str();
            if (name == "velocity" || contains(own, name) ||
                contains(std::span<const std::string_view>(kInitialFieldKeys), name))
                continue;
            fail(s, name,
                 "not used with velocity = \"" + chosen + "\"" +
                     (own.empty() ? std::string(" (it takes no other key)")
                                  : " (it takes " + joinWords(own, "and") + ")"),
                 &node);
        }

        const int modeCount = basis.velocityCount();
        switch (initial.velocity) {
            case InitialVelocity::Zero:
                break;
            case InitialVelocity::Random:
                initial.energy = readNumber(s, "energy", initial.energy, Sign::NonNegative);
                if (auto seed = integer(s, "seed", 0, std::numeric_limits<std::int64_t>::max())) {
                    initial.seed = static_cast<std::uint64_t>(*seed);
                }
                initial.band = readBand(s, modeCount);
                break;
            case InitialVelocity::Modes:
                initial.amplitudes = readAmplitudes(s, modeCount);
                break;
            case InitialVelocity::Vortices:
                initial.energy = readNumber(s, "energy", 0.0, Sign::NonNegative);
                initial.vortices = readVortices(s);
                break;
        }
        readMagnetic(s, initial);
        return initial;
    }

    /// The magnetic field keys of `[initial]` (MHD scenes; the caller checks that).
    void readMagnetic(const Section& s, InitialSpec& initial) const {
        const Choices<InitialMagnetic> choices(kInitialMagnetics);
        initial.magnetic = readChoice(s, "magnetic", initial.magnetic, choices);
        const auto own = magneticKeys(initial.magnetic);
        for (std::string_view key : kInitialFieldKeys) {
            if (key == "magnetic" || contains(own, key) || !s.table.contains(key)) continue;
            fail(s, key,
                 "not used with magnetic = \"" + std::string(keywordOf(choices, initial.magnetic)) +
                     "\" (it takes " + joinWords(own, "and") + ")",
                 s.table.get(key));
        }
        if (initial.magnetic == InitialMagnetic::Uniform) {
            initial.magneticDirection = requireVector(s, "magnetic_direction");
            const Vec3& d = initial.magneticDirection;
            if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 0.0))
                fail(s, "magnetic_direction", "must be a non-zero vector", s.table.get("magnetic_direction"));
            initial.magneticStrength =
                readNumber(s, "magnetic_strength", initial.magneticStrength, Sign::NonNegative);
            initial.magneticWallLayer = readNumber(s, "magnetic_wall_layer", 0.0, Sign::Positive);
            return;
        }
        initial.magneticEnergy =
            readNumber(s, "magnetic_energy", initial.magneticEnergy, Sign::NonNegative);
        if (auto seed = integer(s, "magnetic_seed", 0, std::numeric_limits<std::int64_t>::max()))
            initial.magneticSeed = static_cast<std::uint64_t>(*seed);
    }

    /// `band = [first, last]`: 1-based, inclusive, inside the basis.
    std::optional<ModeRange> readBand(const Section& s, int modeCount) const {
        const toml::node* node = s.table.get("band");
        if (node == nullptr) return std::nullopt;
        const std::string where = s.name + ".band";
        const toml::array* array = node->as_array();
        if (array == nullptr || array->size() != 2) {
            fail(where,
                 "expected [first, last] (two 1-based mode numbers), got " +
                     (array == nullptr ? describeType(*node)
                                       : std::to_string(array->size()) + " entries"),
                 node);
        }
        const std::int64_t first = integerValue((*array)[0], where + "[0]");
        const std::int64_t last = integerValue((*array)[1], where + "[1]");
        if (first < 1) fail(where, "modes are numbered from 1, got " + std::to_string(first), node);
        if (last < first) {
            fail(where,
                 "ends before it starts ([" + std::to_string(first) + ", " +
                     std::to_string(last) + "])",
                 node);
        }
        if (last > modeCount) {
            fail(where,
                 "mode " + std::to_string(last) + " is beyond the basis ([basis] has " +
                     std::to_string(modeCount) + " velocity modes)",
                 node);
        }
        return ModeRange{static_cast<int>(first), static_cast<int>(last)};
    }

    /// `amplitudes = [[mode, amplitude], ...]`, required; modes 1-based, each at most once.
    std::vector<std::pair<int, double>> readAmplitudes(const Section& s, int modeCount) const {
        const toml::node* node = s.table.get("amplitudes");
        if (node == nullptr) {
            fail(s, "amplitudes",
                 "missing required key for velocity = \"modes\" (e.g. [[1, 0.5], [3, -0.2]])");
        }
        const std::string where = s.name + ".amplitudes";
        const toml::array* array = node->as_array();
        if (array == nullptr || array->empty()) {
            fail(where,
                 "expected a non-empty array of [mode, amplitude] pairs, got " +
                     (array == nullptr ? describeType(*node) : std::string("an empty array")),
                 node);
        }
        std::vector<std::pair<int, double>> out;
        for (std::size_t e = 0; e < array->size(); ++e) {
            const toml::node& entry = (*array)[e];
            const std::string at = where + "[" + std::to_string(e) + "]";
            const toml::array* pair = entry.as_array();
            if (pair == nullptr || pair->size() != 2) {
                fail(at,
                     "expected a [mode, amplitude] pair, got " +
                         (pair == nullptr ? describeType(entry)
                                          : std::to_string(pair->size()) + " entries"),
                     &entry);
            }
            const std::int64_t mode = integerValue((*pair)[0], at + "[0]");
            if (mode < 1 || mode > modeCount) {
                fail(at,
                     "mode " + std::to_string(mode) + " is outside the basis (modes 1 to " +
                         std::to_string(modeCount) + ")",
                     &entry);
            }
            for (const auto& [m, a] : out) {
                if (m == mode) fail(at, "mode " + std::to_string(mode) + " is given twice", &entry);
            }
            out.emplace_back(static_cast<int>(mode), numberValue((*pair)[1], at + "[1]"));
        }
        return out;
    }

    /// `[[initial.vortex]]` entries, at least one.
    std::vector<VortexSpec> readVortices(const Section& s) const {
        const toml::node* node = s.table.get("vortex");
        const std::string where = "[[initial.vortex]]";
        if (node == nullptr) {
            fail(where, "missing: velocity = \"vortices\" needs at least one [[initial.vortex]]",
                 &s.table);
        }
        const toml::array* array = node->as_array();
        if (array == nullptr || !array->is_array_of_tables() || array->empty()) {
            fail(where,
                 "expected an array of tables (write [[initial.vortex]]), got " +
                     describeType(*node),
                 node);
        }
        const auto keys = mDim == 2 ? std::span<const std::string_view>(kVortexKeys2d)
                                    : std::span<const std::string_view>(kVortexKeys3d);
        std::vector<VortexSpec> out;
        int index = 0;
        for (const toml::node& entry : *array) {
            ++index;
            const Section v{*entry.as_table(), where + " #" + std::to_string(index)};
            for (const auto& [key, value] : v.table) {
                if (mDim == 2 && (key.str() == "normal" || key.str() == "ring_radius")) {
                    fail(v, key.str(),
                         "only 3D vortex rings take it, but this scene is 2D ([grid].resolution "
                         "has 2 entries)",
                         &value);
                }
            }
            checkKeys(v, keys);
            VortexSpec vortex;
            vortex.center = requireVector(v, "center");
            if (!v.table.contains("strength")) fail(v, "strength", "missing required key");
            vortex.strength = readNumber(v, "strength", 0.0);
            vortex.radius = requireNumber(v, "radius", Sign::Positive);
            if (mDim == 3) {
                vortex.normal = requireVector(v, "normal");
                const Vec3& n = vortex.normal;
                if (!(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0.0)) {
                    fail(v, "normal", "must be a non-zero vector", v.table.get("normal"));
                }
                vortex.ringRadius = requireNumber(v, "ring_radius", Sign::Positive);
            }
            out.push_back(vortex);
        }
        return out;
    }

    SourceSpec readSource(const toml::table& table, int index) const {
        SourceSpec source;
        source.shape = readShape(table, "[[source]]", index, false);
        const Section s{
            table, "[[source]] #" + std::to_string(index) + " (" +
                       std::string(keywordOf(Choices<ShapeKind>(kShapeKinds), source.shape.kind)) +
                       ")"};
        source.density = readNumber(s, "density", source.density, Sign::NonNegative);
        source.temperature = readNumber(s, "temperature", source.temperature);
        source.start = readNumber(s, "start", source.start, Sign::NonNegative);
        source.end = readNumber(s, "end", source.end, Sign::Positive);
        if (source.end <= source.start)
            fail(s, "end", "must be later than start (" + std::to_string(source.start) + ")", table.get("end"));
        return source;
    }

    ObstacleSpec readObstacle(const Section& s) const {
        checkKeys(s, kObstacleKeys);
        if (!s.table.contains("shape")) fail(s, "shape", "missing required key (one of ball, box or capsule)");
        ObstacleSpec obstacle;
        obstacle.shape = readChoice(s, "shape", obstacle.shape, Choices<ObstacleShape>(kObstacleShapes));
        const auto unused = [&](std::string_view key) {
            if (s.table.contains(key))
                fail(s, key, "not used by a " + std::string(keywordOf(Choices<ObstacleShape>(kObstacleShapes),
                                                                       obstacle.shape)),
                     s.table.get(key));
        };
        if (obstacle.shape == ObstacleShape::Box) {
            obstacle.halfSize = requireVector(s, "half_size");
            for (int a = 0; a < mDim; ++a)
                if (!(obstacle.halfSize[a] > 0.0)) fail(s, "half_size", "every entry must be > 0", s.table.get("half_size"));
            unused("radius");
            unused("axis");
        } else {
            obstacle.radius = requireNumber(s, "radius", Sign::Positive);
            unused("half_size");
            if (obstacle.shape == ObstacleShape::Capsule) obstacle.axis = requireVector(s, "axis");
            else unused("axis");
        }
        const toml::node* node = s.table.get("path");
        const std::string where = s.name + ".path";
        const toml::array* path = node ? node->as_array() : nullptr;
        if (path == nullptr || path->empty())
            fail(where, "expected an array of key frames [t, x, y" + std::string(mDim == 3 ? ", z" : "") + "]",
                 node ? node : &s.table);
        for (const toml::node& entry : *path) {
            const toml::array* frame = entry.as_array();
            if (frame == nullptr || frame->size() != std::size_t(mDim + 1))
                fail(where, "each key frame is " + std::to_string(mDim + 1) + " numbers [t, position]", &entry);
            const double t = numberValue((*frame)[0], where + " time");
            Vec3 position{0.0, 0.0, 0.0};
            for (int a = 0; a < mDim; ++a) position[a] = numberValue((*frame)[std::size_t(a + 1)], where);
            if (!obstacle.path.empty() && !(t > obstacle.path.back().first))
                fail(where, "key frame times must increase", &entry);
            obstacle.path.emplace_back(t, position);
        }
        return obstacle;
    }

    SmokeSpec readSmoke(const Section& s, const GridSpec& grid) const {
        checkKeys(s, kSmokeKeys);
        SmokeSpec smoke;
        smoke.buoyancy = readNumber(s, "buoyancy", smoke.buoyancy);
        smoke.resolutionScale = readInt(s, "resolution_scale", smoke.resolutionScale, 1, 8);
        smoke.advection = readChoice(s, "advection", smoke.advection, Choices<AdvectionScheme>(kAdvectionSchemes));
        std::int64_t cells = 1;
        for (int a = 0; a < grid.dim; ++a) {
            cells *= std::int64_t{grid.resolution[a]} * smoke.resolutionScale;
        }
        if (cells > kMaxSmokeCells) {
            fail(s, "resolution_scale",
                 "a smoke grid of " + std::to_string(cells) +
                     " cells is absurdly large (the limit is 2^31 cells)",
                 s.table.get("resolution_scale"));
        }
        return smoke;
    }

    OutputSpec readOutput(const Section& s) const {
        checkKeys(s, kOutputKeys);
        OutputSpec output;
        output.frames = readInt(s, "frames", output.frames, 1);
        output.stepsPerFrame = readInt(s, "steps_per_frame", output.stepsPerFrame, 1);
        return output;
    }
};

}  // namespace

std::vector<ModeRange> parseModeRanges(std::string_view text, std::string_view key) {
    std::vector<ModeRange> ranges;
    if (auto problem = parseModeList(text, ranges)) {
        throw Error(std::string(key) + ": bad mode list \"" + std::string(text) +
                    "\": " + *problem);
    }
    return ranges;
}

SceneSpec parseScene(std::string_view text, const std::filesystem::path& origin) {
    try {
        return SceneParser(origin).parse(text);
    } catch (const Error& e) {
        // Messages quote the file (keys, values, the byte the TOML parser stopped at): control
        // characters and broken UTF-8 must not reach the terminal.
        throw Error(printableText(e.what()));
    }
}

SceneSpec loadScene(const std::filesystem::path& file) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) {
        throw Error(file.string() + ": no such scene file");
    }
    if (std::filesystem::is_directory(status)) {
        throw Error(file.string() + ": is a folder, not a scene file");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw Error(file.string() + ": cannot open the scene file (" + std::strerror(errno) + ")");
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error(file.string() + ": error while reading the scene file");
    return parseScene(text.str(), file);
}

std::string_view sceneKeyword(ShapeKind kind) {
    return keywordOf(Choices<ShapeKind>(kShapeKinds), kind);
}
std::string_view sceneKeyword(CsgOp op) {
    return keywordOf(Choices<CsgOp>(kCsgOps), op);
}
std::string_view sceneKeyword(ScalarBoundary boundary) {
    return keywordOf(Choices<ScalarBoundary>(kScalarBoundaries), boundary);
}
std::string_view sceneKeyword(WallKind wall) {
    return keywordOf(Choices<WallKind>(kWalls), wall);
}
std::string_view sceneKeyword(BoundaryTreatment treatment) {
    return keywordOf(Choices<BoundaryTreatment>(kBoundaries), treatment);
}
std::string_view sceneKeyword(Integrator integrator) {
    return keywordOf(Choices<Integrator>(kIntegrators), integrator);
}
Integrator parseIntegrator(std::string_view text, std::string_view key) {
    std::vector<std::string_view> names;
    for (const auto& [name, value] : kIntegrators) {
        if (name == text) return value;
        names.push_back(name);
    }
    std::string what = std::string(key) + ": unknown integrator \"" + std::string(text) + "\"";
    if (auto guess = closest(text, names)) what += " (did you mean " + std::string(*guess) + "?)";
    throw Error(what + "; expected " + joinWords(names));
}

std::string_view sceneKeyword(InitialVelocity velocity) {
    return keywordOf(Choices<InitialVelocity>(kInitialVelocities), velocity);
}

}  // namespace modeflow
