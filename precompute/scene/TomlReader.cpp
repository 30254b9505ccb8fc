/// @file TomlReader.cpp

#include "precompute/scene/TomlReader.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/core/Error.h"
#include "engine/core/PrintableText.h"
#include "precompute/scene/SceneLoader.h"

namespace modeflow::scene {
namespace {

[[noreturn]] void throwSyntaxError(const std::string& file, const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw Error(file + ": line " + std::to_string(begin.line) + ", column " +
                std::to_string(begin.column) +
                ": TOML syntax error: " + printableText(e.description(), 200));
}

}  // namespace

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

TomlReader::TomlReader(const std::filesystem::path& origin)
    : mFile(origin.string()), mOrigin(origin) {}

toml::table TomlReader::parse(std::string_view text) const {
    checkNesting(text);
#if TOML_EXCEPTIONS
    try {
        return toml::parse(text, mFile);
    } catch (const toml::parse_error& e) {
        throwSyntaxError(mFile, e);
    }
#else
    toml::parse_result result = toml::parse(text, mFile);
    if (!result) throwSyntaxError(mFile, result.error());
    return std::move(result).table();
#endif
}

void TomlReader::checkNesting(std::string_view text) const {
    std::size_t line = 1, lineStart = 0;
    int dots = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
            dots = 0;
        } else if (text[i] == '.' && ++dots > kMaxDotsPerLine) {
            const std::string_view rest = text.substr(lineStart);
            const std::string_view whole = rest.substr(0, rest.find('\n'));
            throw Error(mFile + ": line " + std::to_string(line) + ": " +
                        std::to_string(std::count(whole.begin(), whole.end(), '.')) +
                        " dots on one line (at most " + std::to_string(kMaxDotsPerLine) +
                        "): each dot of a key nests a table, and nesting that deep is refused; "
                        "spread long arrays of numbers over several lines");
        }
    }
}

// ---- messages -------------------------------------------------------------------------------

void TomlReader::fail(std::string_view where, std::string_view what, const toml::node* at) const {
    std::string message = mFile + ": " + std::string(where) + ": " + std::string(what);
    if (at != nullptr && at->source().begin.line > 0) {
        message += " (line " + std::to_string(at->source().begin.line) + ")";
    }
    throw Error(message);
}

void TomlReader::fail(const Section& s, std::string_view key, std::string_view what,
                      const toml::node* at) const {
    // Keys come from the file: a TOML escape can put a terminal command in one.
    fail(s.name + "." + printableText(key), what, at != nullptr ? at : &s.table);
}

// ---- structure ------------------------------------------------------------------------------

const toml::table* TomlReader::optionalTable(const toml::table& root, std::string_view name) const {
    const toml::node* node = root.get(name);
    if (node == nullptr) return nullptr;
    if (!node->is_table()) {
        fail("[" + std::string(name) + "]", "expected a table, got " + describeType(*node), node);
    }
    return node->as_table();
}

const toml::table* TomlReader::requireTable(const toml::table& root, std::string_view name) const {
    const toml::table* table = optionalTable(root, name);
    if (table == nullptr) {
        fail("[" + std::string(name) + "]", "missing required table");
    }
    return table;
}

void TomlReader::checkKeys(const Section& s, std::span<const std::string_view> allowed) const {
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

// ---- values ---------------------------------------------------------------------------------

std::optional<double> TomlReader::number(const Section& s, std::string_view key) const {
    const toml::node* node = s.table.get(key);
    if (node == nullptr) return std::nullopt;
    return numberValue(*node, s.name + "." + std::string(key));
}

double TomlReader::numberValue(const toml::node& node, const std::string& where) const {
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

double TomlReader::readNumber(const Section& s, std::string_view key, double fallback,
                              Sign sign) const {
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

double TomlReader::requireNumber(const Section& s, std::string_view key, Sign sign) const {
    if (!s.table.contains(key)) fail(s, key, "missing required key");
    return readNumber(s, key, 0.0, sign);
}

std::int64_t TomlReader::integerValue(const toml::node& node, const std::string& where) const {
    const auto* i = node.as_integer();
    if (i == nullptr) fail(where, "expected an integer, got " + describeType(node), &node);
    return i->get();
}

std::optional<std::int64_t> TomlReader::integer(const Section& s, std::string_view key,
                                                std::int64_t lo, std::int64_t hi) const {
    const toml::node* node = s.table.get(key);
    if (node == nullptr) return std::nullopt;
    const std::int64_t value = integerValue(*node, s.name + "." + std::string(key));
    if (value < lo || value > hi) {
        // Limits that only guard against overflow are not worth mentioning unless hit.
        const bool openEnded =
            hi == std::numeric_limits<std::int64_t>::max() || hi == std::numeric_limits<int>::max();
        std::string what =
            !openEnded   ? "must be between " + std::to_string(lo) + " and " + std::to_string(hi)
            : value < lo ? "must be at least " + std::to_string(lo)
                         : "is too large (at most " + std::to_string(hi) + ")";
        fail(s, key, what + ", got " + std::to_string(value), node);
    }
    return value;
}

int TomlReader::readInt(const Section& s, std::string_view key, int fallback, int lo,
                        int hi) const {
    const auto value = integer(s, key, lo, hi);
    return value ? static_cast<int>(*value) : fallback;
}

std::optional<std::string> TomlReader::string(const Section& s, std::string_view key) const {
    const toml::node* node = s.table.get(key);
    if (node == nullptr) return std::nullopt;
    const auto* str = node->as_string();
    if (str == nullptr) fail(s, key, "expected a string, got " + describeType(*node), node);
    return str->get();
}

std::optional<Vec3> TomlReader::vector(const Section& s, std::string_view key) const {
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

Vec3 TomlReader::requireVector(const Section& s, std::string_view key) const {
    const std::optional<Vec3> v = vector(s, key);
    if (!v) fail(s, key, "missing required key");
    return *v;
}

}  // namespace modeflow::scene
