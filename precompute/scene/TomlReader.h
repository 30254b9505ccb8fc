#pragma once
/// @file TomlReader.h
/// Internal to precompute/scene (the only place toml++ is seen): a parsed scene file read with
/// messages that name the file, the key and the line, e.g.
/// "scenes/x.toml: [grid].resolution: expected 2 or 3 integers, got 4 entries (line 2)".

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "engine/core/PrintableText.h"
#include "engine/core/SceneSpec.h"
#include "precompute/scene/SceneSchema.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

/// A table and the name messages give it ("[grid]", "[[domain]] #2 (torus)").
struct Section {
    const toml::table& table;
    std::string name;
};

/// Lower/upper limits a number must respect.
enum class Sign { Any, NonNegative, Positive };

/// "an integer", "a string", "a floating-point number (2.5)", ...
std::string describeType(const toml::node& node);

class TomlReader {
public:
    /// `origin` names the file in messages and resolves relative paths.
    explicit TomlReader(const std::filesystem::path& origin);

    const std::filesystem::path& origin() const { return mOrigin; }

    /// The scene's dimension, which every vector read has; the [grid] reader sets it.
    int dimension() const { return mDim; }
    void setDimension(int dim) { mDim = dim; }

    /// @throw Error "<file>: line L, column C: TOML syntax error: ..."
    toml::table parse(std::string_view text) const;

    // ---- messages ---------------------------------------------------------------------------

    /// @throw Error "<file>: <where>: <what> (line N)", the line being `at`'s when known.
    [[noreturn]] void fail(std::string_view where, std::string_view what,
                           const toml::node* at = nullptr) const;
    /// Same, for `s.name + "." + key`; the line is `at`'s, or the table's.
    [[noreturn]] void fail(const Section& s, std::string_view key, std::string_view what,
                           const toml::node* at = nullptr) const;

    // ---- structure --------------------------------------------------------------------------

    const toml::table* optionalTable(const toml::table& root, std::string_view name) const;
    const toml::table* requireTable(const toml::table& root, std::string_view name) const;

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
    void checkKeys(const Section& s, std::span<const std::string_view> allowed) const;

    // ---- values -----------------------------------------------------------------------------

    std::optional<double> number(const Section& s, std::string_view key) const;
    /// A float, or an integer standing for one (`radius = 1`); finite.
    double numberValue(const toml::node& node, const std::string& where) const;
    double readNumber(const Section& s, std::string_view key, double fallback,
                      Sign sign = Sign::Any) const;
    double requireNumber(const Section& s, std::string_view key, Sign sign) const;

    std::int64_t integerValue(const toml::node& node, const std::string& where) const;
    std::optional<std::int64_t> integer(const Section& s, std::string_view key, std::int64_t lo,
                                        std::int64_t hi) const;
    int readInt(const Section& s, std::string_view key, int fallback, int lo,
                int hi = std::numeric_limits<int>::max()) const;

    std::optional<std::string> string(const Section& s, std::string_view key) const;

    template <typename T>
    T readChoice(const Section& s, std::string_view key, T fallback, Choices<T> choices) const {
        const std::optional<std::string> value = string(s, key);
        if (!value) return fallback;
        std::vector<std::string_view> names;
        for (const auto& [name, v] : choices) {
            if (name == *value) return v;
            names.push_back(name);
        }
        std::string what = "unknown value \"" + printableText(*value) + "\"";
        if (auto guess = closest(*value, names))
            what += " (did you mean " + std::string(*guess) + "?)";
        fail(s, key, what + "; expected " + joinWords(names), s.table.get(key));
    }

    /// A point or extent with the scene's dimension; 2D leaves the third entry at 0.
    std::optional<Vec3> vector(const Section& s, std::string_view key) const;
    Vec3 requireVector(const Section& s, std::string_view key) const;

private:
    /// Refuses a line with more than kMaxDotsPerLine dots before toml++ recurses into it.
    void checkNesting(std::string_view text) const;

    std::string mFile;
    std::filesystem::path mOrigin;
    int mDim = 2;
};

}  // namespace modeflow::scene
