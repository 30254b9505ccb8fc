#pragma once
/// @file SceneWording.h
/// Internal to precompute/scene: the words scene messages are made of (typo suggestions, lists,
/// numbers, axis names).

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace modeflow::scene {

bool contains(std::span<const std::string_view> list, std::string_view item);

/// The closest candidate, if it is close enough to be a plausible typo.
std::optional<std::string_view> closest(std::string_view word,
                                        std::span<const std::string_view> candidates);

/// "a, b or c"
std::string joinWords(std::span<const std::string_view> words, std::string_view last = "or");

/// The shortest text that reads back as `x`.
std::string formatNumber(double x);

/// "2.5e+299": two significant digits, for numbers that only need to be recognised.
std::string roughNumber(double x);

/// "x", "y" or "z".
const char* axisName(int axis);

/// "x_min" ... "z_max" for side 2·axis + (0 low, 1 high).
std::string sideName(int side);
/// The side a name such as "y_max" names in a `dim`-D box; -1 for none.
int sideNamed(std::string_view name, int dim);
/// "x_min, x_max, y_min, y_max" (", z_min or z_max" in 3D): the sides of a `dim`-D box.
std::string sideNames(int dim);

/// Why fuel (a source's, an inflow's) is refused without a [fire] table.
inline constexpr const char* kFuelNeedsFire =
    "fuel burns by a [fire] table (ignition, burn_rate, heat, smoke), which the scene lacks";

}  // namespace modeflow::scene
