#pragma once
/// @file MantaflowPlume.h
/// The outside check of `reduced_vs_full`'s 3D plume: mantaflow_plume.py (embedded at build time)
/// run in Blender, headless, on the study's scene (tools/validate/README.md, "The outside check").

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace modeflow::validate {

/// The Blender that runs the check, or why there is none.
struct BlenderChoice {
    std::filesystem::path program;  ///< empty when none
    std::string absence;            ///< why none, in words for the report
};

/// `requested` (--blender) when given, else `blender` on the PATH.
/// @throw modeflow::Error when `requested` is not an executable file.
BlenderChoice findBlender(const std::optional<std::string>& requested);

/// Runs the script in `blender -b --factory-startup` for a `resolution`³ domain and `frames`
/// frames of 0.02 s (Blender's messages go to stderr) and returns the JSON it writes: per frame
/// the smoke centroid height and the peak face speed.
/// @throw modeflow::Error when Blender cannot be started, fails, or writes no result.
nlohmann::json runMantaflowPlume(const std::filesystem::path& blender, int resolution, int frames);

}  // namespace modeflow::validate
