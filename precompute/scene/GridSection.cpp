/// @file GridSection.cpp
/// `[grid]`: resolution (2 or 3 entries, which sets the scene's dimension), bounds, periodic axes
/// and open sides.

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {
namespace {

// Within the cell size limits, volumes, areas and 1/h² are normal doubles, far from overflow.
constexpr double kLeast = std::numeric_limits<double>::min(),
                 kMost = std::numeric_limits<double>::max();
static_assert(kMinCellSize * kMinCellSize * kMinCellSize > kLeast * 1e100);
static_assert(kMaxCellSize * kMaxCellSize * kMaxCellSize < kMost * 1e-100);
static_assert(1.0 / (kMinCellSize * kMinCellSize) < kMost * 1e-100);

/// Decimal bounds divide with rounding: a limit met exactly in the file must pass.
constexpr double kRounding = 1e-9;

/// Bounds that give cells too small, too large, too stretched or too far from the origin.
void checkCellSizes(const TomlReader& reader, const Section& s, const GridSpec& grid) {
    const std::string_view pair = "bounds_min/bounds_max";
    const toml::node* at = s.table.get("bounds_max");
    for (int a = 0; a < grid.dim; ++a) {
        const double h = grid.spacing(a);
        const std::string along = std::string(" along ") + axisName(a);
        if (!std::isfinite(grid.boundsMax[a] - grid.boundsMin[a]))
            reader.fail(s, pair, "bounds_max - bounds_min" + along + " is not a finite number", at);
        if (h < kMinCellSize * (1.0 - kRounding) || h > kMaxCellSize * (1.0 + kRounding)) {
            reader.fail(s, pair,
                        "cells of " + formatNumber(h) + along + " are " +
                            (h < kMinCellSize ? "smaller than " + formatNumber(kMinCellSize)
                                              : "larger than " + formatNumber(kMaxCellSize)) +
                            " (scene units per cell); scale the scene",
                        at);
        }
    }
    int longest = 0, shortest = 0;
    for (int a = 1; a < grid.dim; ++a) {
        if (grid.spacing(a) > grid.spacing(longest)) longest = a;
        if (grid.spacing(a) < grid.spacing(shortest)) shortest = a;
    }
    const double ratio = grid.spacing(longest) / grid.spacing(shortest);
    if (ratio > kMaxCellAspectRatio * (1.0 + kRounding)) {
        reader.fail(s, pair,
                    "cells are " + formatNumber(std::round(ratio)) + " times longer along " +
                        axisName(longest) + " (" + formatNumber(grid.spacing(longest)) +
                        ") than along " + axisName(shortest) + " (" +
                        formatNumber(grid.spacing(shortest)) + "); at most " +
                        formatNumber(kMaxCellAspectRatio) + ": raise the resolution along " +
                        axisName(longest),
                    at);
    }
    for (int a = 0; a < grid.dim; ++a) {
        const bool maxIsFarther = std::abs(grid.boundsMax[a]) >= std::abs(grid.boundsMin[a]);
        const double cells =
            std::abs(maxIsFarther ? grid.boundsMax[a] : grid.boundsMin[a]) / grid.spacing(a);
        if (cells > kMaxCellsFromOrigin * (1.0 + kRounding)) {
            reader.fail(s, maxIsFarther ? "bounds_max" : "bounds_min",
                        "the grid lies " + roughNumber(cells) + " cells (of " +
                            formatNumber(grid.spacing(a)) + ") from the origin along " +
                            axisName(a) + "; at most " + roughNumber(kMaxCellsFromOrigin) +
                            ": coordinates that far out lose their precision; move the grid "
                            "nearer the origin",
                        s.table.get(maxIsFarther ? "bounds_max" : "bounds_min"));
        }
    }
}

/// `periodic = [true, false]`: one flag per axis, default all false.
void readPeriodicAxes(const TomlReader& reader, const Section& s, GridSpec& grid) {
    const toml::node* node = s.table.get("periodic");
    if (node == nullptr) return;
    const toml::array* array = node->as_array();
    if (array == nullptr || int(array->size()) != grid.dim)
        reader.fail(s, "periodic",
                    "expected " + std::to_string(grid.dim) +
                        " booleans (one per axis, like resolution), got " +
                        (array ? std::to_string(array->size()) + " entries" : describeType(*node)),
                    node);
    for (int a = 0; a < grid.dim; ++a) {
        const toml::node& flag = (*array)[std::size_t(a)];
        const std::optional<bool> value = flag.value<bool>();
        if (!flag.is_boolean() || !value)
            reader.fail(s.name + ".periodic[" + std::to_string(a) + "]",
                        "expected true or false, got " + describeType(flag), &flag);
        grid.periodic[std::size_t(a)] = *value;
    }
}

/// `open = ["y_max"]`: the sides the air may cross, by name; none by default.
void readOpenSides(const TomlReader& reader, const Section& s, GridSpec& grid) {
    const toml::node* node = s.table.get("open");
    if (node == nullptr) return;
    const toml::array* array = node->as_array();
    if (array == nullptr)
        reader.fail(s, "open",
                    "expected an array of side names (\"x_min\" ... \"" +
                        std::string(grid.dim == 2 ? "y_max" : "z_max") + "\"), got " +
                        describeType(*node),
                    node);
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& entry = (*array)[i];
        const std::string where = s.name + ".open[" + std::to_string(i) + "]";
        const std::optional<std::string> name = entry.value<std::string>();
        const int side = name ? sideNamed(*name, grid.dim) : -1;
        if (side < 0)
            reader.fail(where,
                        "expected a side of the " + std::to_string(grid.dim) +
                            "D box: " + sideNames(grid.dim) + ", got " +
                            (name ? "\"" + *name + "\"" : describeType(entry)),
                        &entry);
        if (grid.open[std::size_t(side)])
            reader.fail(where, "\"" + *name + "\" is listed twice", &entry);
        if (grid.isPeriodic(side / 2))
            reader.fail(where,
                        "\"" + *name +
                            "\" lies across a periodic axis, whose ends are one plane "
                            "with no side to open",
                        &entry);
        grid.open[std::size_t(side)] = true;
    }
}

}  // namespace

GridSpec readGrid(TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kGridKeys);
    GridSpec grid;
    const toml::node* node = s.table.get("resolution");
    if (node == nullptr) reader.fail(s, "resolution", "missing required key");
    const toml::array* array = node->as_array();
    if (array == nullptr) {
        reader.fail(s, "resolution",
                    "expected an array of 2 or 3 integers, got " + describeType(*node), node);
    }
    if (array->size() != 2 && array->size() != 3) {
        reader.fail(s, "resolution",
                    "expected 2 or 3 integers, got " + std::to_string(array->size()) +
                        (array->size() == 1 ? " entry" : " entries"),
                    node);
    }
    grid.dim = static_cast<int>(array->size());
    std::int64_t cells = 1;
    for (int a = 0; a < grid.dim; ++a) {
        const std::string where = s.name + ".resolution[" + std::to_string(a) + "]";
        const std::int64_t n = reader.integerValue((*array)[a], where);
        if (n < 2 || n > kMaxGridResolution) {
            reader.fail(where,
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
        reader.fail(s, "resolution",
                    dims + " = " + std::to_string(cells) +
                        " cells is absurdly large (the limit is 134217728 = 2^27 cells)",
                    node);
    }

    reader.setDimension(grid.dim);  // every vector from here on has the grid's dimension
    const Vec3 lo = reader.requireVector(s, "bounds_min");
    const Vec3 hi = reader.requireVector(s, "bounds_max");
    for (int a = 0; a < grid.dim; ++a) {
        if (!(hi[a] > lo[a])) {
            reader.fail(s, "bounds_max",
                        std::string("must exceed bounds_min on every axis, but on axis ") +
                            axisName(a) + " bounds_min = " + formatNumber(lo[a]) +
                            " and bounds_max = " + formatNumber(hi[a]) + " (inverted bounds)",
                        s.table.get("bounds_max"));
        }
        grid.boundsMin[a] = lo[a];
        grid.boundsMax[a] = hi[a];
    }
    checkCellSizes(reader, s, grid);
    readPeriodicAxes(reader, s, grid);
    readOpenSides(reader, s, grid);
    return grid;
}

}  // namespace modeflow::scene
