#pragma once
/// @file ModeList.h
/// Internal to precompute/scene: mode lists such as "1-115,516-630" (SceneLoader.h's
/// parseModeRanges is the public face).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/SceneSpec.h"

namespace modeflow::scene {

/// Parses a mode list into `out`; returns the problem, or nothing when `out` is valid.
std::optional<std::string> parseModeList(std::string_view text, std::vector<ModeRange>& out);

}  // namespace modeflow::scene
