#include "engine/dynamics/TimeScheme.h"

#include <array>
#include <string>
#include <utility>

#include "engine/format/Error.h"

namespace modeflow {
namespace {

constexpr std::array<std::pair<TimeScheme, std::string_view>, 4> kNames{{
    {TimeScheme::ExplicitEuler, "explicit"},
    {TimeScheme::RungeKutta4, "rk4"},
    {TimeScheme::Midpoint, "midpoint"},
    {TimeScheme::Trapezoidal, "trapezoidal"},
}};

}  // namespace

TimeScheme parseTimeScheme(std::string_view name) {
    for (const auto& [scheme, schemeName] : kNames) {
        if (name == schemeName) return scheme;
    }
    throw Error("unknown integrator \"" + std::string(name) +
                "\" (expected explicit, rk4, midpoint or trapezoidal)");
}

std::string_view timeSchemeName(TimeScheme scheme) {
    for (const auto& [s, schemeName] : kNames) {
        if (s == scheme) return schemeName;
    }
    return "unknown";
}

}  // namespace modeflow
