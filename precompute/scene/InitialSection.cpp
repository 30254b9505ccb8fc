/// @file InitialSection.cpp
/// `[initial]`: the initial velocity (zero, random, given modal amplitudes or vortices) and, in
/// MHD scenes, the initial magnetic field. Whether modes lie in the basis is checked in
/// SceneValidation.

#include <cstdint>
#include <limits>

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {
namespace {

/// The magnetic field keys of `[initial]` (MHD scenes; the caller checks that).
void readMagnetic(const TomlReader& reader, const Section& s, InitialSpec& initial) {
    const Choices<InitialMagnetic> choices(kInitialMagnetics);
    initial.magnetic = reader.readChoice(s, "magnetic", initial.magnetic, choices);
    const auto own = magneticKeys(initial.magnetic);
    for (std::string_view key : kInitialFieldKeys) {
        if (key == "magnetic" || contains(own, key) || !s.table.contains(key)) continue;
        reader.fail(s, key,
                    "not used with magnetic = \"" +
                        std::string(keywordOf(choices, initial.magnetic)) + "\" (it takes " +
                        joinWords(own, "and") + ")",
                    s.table.get(key));
    }
    if (initial.magnetic == InitialMagnetic::Uniform) {
        initial.magneticDirection = reader.requireVector(s, "magnetic_direction");
        const Vec3& d = initial.magneticDirection;
        if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 0.0))
            reader.fail(s, "magnetic_direction", "must be a non-zero vector",
                        s.table.get("magnetic_direction"));
        initial.magneticStrength =
            reader.readNumber(s, "magnetic_strength", initial.magneticStrength, Sign::NonNegative);
        initial.magneticWallLayer =
            reader.readNumber(s, "magnetic_wall_layer", 0.0, Sign::Positive);
        return;
    }
    initial.magneticEnergy =
        reader.readNumber(s, "magnetic_energy", initial.magneticEnergy, Sign::NonNegative);
    if (auto seed = reader.integer(s, "magnetic_seed", 0, std::numeric_limits<std::int64_t>::max()))
        initial.magneticSeed = static_cast<std::uint64_t>(*seed);
}

/// `band = [first, last]`: 1-based, inclusive.
std::optional<ModeRange> readBand(const TomlReader& reader, const Section& s) {
    const toml::node* node = s.table.get("band");
    if (node == nullptr) return std::nullopt;
    const std::string where = s.name + ".band";
    const toml::array* array = node->as_array();
    if (array == nullptr || array->size() != 2) {
        reader.fail(where,
                    "expected [first, last] (two 1-based mode numbers), got " +
                        (array == nullptr ? describeType(*node)
                                          : std::to_string(array->size()) + " entries"),
                    node);
    }
    const std::int64_t first = reader.integerValue((*array)[0], where + "[0]");
    const std::int64_t last = reader.integerValue((*array)[1], where + "[1]");
    if (first < 1)
        reader.fail(where, "modes are numbered from 1, got " + std::to_string(first), node);
    if (last < first) {
        reader.fail(
            where,
            "ends before it starts ([" + std::to_string(first) + ", " + std::to_string(last) + "])",
            node);
    }
    // Narrowed here; SceneValidation compares the file's own numbers with the basis.
    return ModeRange{static_cast<int>(first), static_cast<int>(last)};
}

/// `amplitudes = [[mode, amplitude], ...]`, required; each mode at most once.
std::vector<std::pair<int, double>> readAmplitudes(const TomlReader& reader, const Section& s) {
    const toml::node* node = s.table.get("amplitudes");
    if (node == nullptr) {
        reader.fail(s, "amplitudes",
                    "missing required key for velocity = \"modes\" (e.g. [[1, 0.5], [3, -0.2]])");
    }
    const std::string where = s.name + ".amplitudes";
    const toml::array* array = node->as_array();
    if (array == nullptr || array->empty()) {
        reader.fail(where,
                    "expected a non-empty array of [mode, amplitude] pairs, got " +
                        (array == nullptr ? describeType(*node) : std::string("an empty array")),
                    node);
    }
    std::vector<std::pair<int, double>> out;
    std::vector<std::int64_t> modes;  // as written, before narrowing
    for (std::size_t e = 0; e < array->size(); ++e) {
        const toml::node& entry = (*array)[e];
        const std::string at = where + "[" + std::to_string(e) + "]";
        const toml::array* pair = entry.as_array();
        if (pair == nullptr || pair->size() != 2) {
            reader.fail(at,
                        "expected a [mode, amplitude] pair, got " +
                            (pair == nullptr ? describeType(entry)
                                             : std::to_string(pair->size()) + " entries"),
                        &entry);
        }
        const std::int64_t mode = reader.integerValue((*pair)[0], at + "[0]");
        for (const std::int64_t m : modes) {
            if (m == mode)
                reader.fail(at, "mode " + std::to_string(mode) + " is given twice", &entry);
        }
        modes.push_back(mode);
        out.emplace_back(static_cast<int>(mode), reader.numberValue((*pair)[1], at + "[1]"));
    }
    return out;
}

}  // namespace

InitialSpec readInitial(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kInitialKeys);
    InitialSpec initial;
    const Choices<InitialVelocity> choices(kInitialVelocities);
    initial.velocity = reader.readChoice(s, "velocity", initial.velocity, choices);
    // A key of another choice would be silently ignored, which hides a mistaken choice.
    const std::string chosen(keywordOf(choices, initial.velocity));
    const auto own = initialKeys(initial.velocity);
    for (const auto& [key, node] : s.table) {
        const std::string_view name = key.str();
        if (name == "velocity" || contains(own, name) ||
            contains(std::span<const std::string_view>(kInitialFieldKeys), name))
            continue;
        reader.fail(s, name,
                    "not used with velocity = \"" + chosen + "\"" +
                        (own.empty() ? std::string(" (it takes no other key)")
                                     : " (it takes " + joinWords(own, "and") + ")"),
                    &node);
    }

    switch (initial.velocity) {
        case InitialVelocity::Zero:
            break;
        case InitialVelocity::Random:
            initial.energy = reader.readNumber(s, "energy", initial.energy, Sign::NonNegative);
            if (auto seed =
                    reader.integer(s, "seed", 0, std::numeric_limits<std::int64_t>::max())) {
                initial.seed = static_cast<std::uint64_t>(*seed);
            }
            initial.band = readBand(reader, s);
            break;
        case InitialVelocity::Modes:
            initial.amplitudes = readAmplitudes(reader, s);
            break;
        case InitialVelocity::Vortices:
            initial.energy = reader.readNumber(s, "energy", 0.0, Sign::NonNegative);
            initial.vortices = readVortices(reader, s);
            break;
    }
    readMagnetic(reader, s, initial);
    return initial;
}

}  // namespace modeflow::scene
