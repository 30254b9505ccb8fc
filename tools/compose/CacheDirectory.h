#pragma once
/// @file CacheDirectory.h
/// Where basis caches live when a command (or the Python module) names no folder.

#include <filesystem>
#include <optional>
#include <string>

namespace modeflow {

/// `option` (--cache-dir, cache_dir=), else $MODEFLOW_CACHE_DIR, else $XDG_CACHE_HOME/modeflow,
/// else ~/.cache/modeflow.
/// @throw modeflow::Error when none of them is set.
std::filesystem::path resolveCacheDir(const std::optional<std::string>& option);

}  // namespace modeflow
