/// @file GridSection.cpp
/// `[grid]`: resolution (2 or 3 entries, which sets the scene's dimension) and bounds.

#include <cstdint>

#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

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
    return grid;
}

}  // namespace modeflow::scene
