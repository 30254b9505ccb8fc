#pragma once
/// @file PngReader.h
/// PNG files back into Images (stb_image): what contact sheets made from the previews a run
/// wrote read.

#include <filesystem>

#include "engine/preview/Image.h"

namespace modeflow::preview {

/// The picture in `file` as RGBA (grey or RGB files get opaque alpha).
/// @throw modeflow::Error naming `file` when it is missing, unreadable, or no PNG stb can read.
Image readPng(const std::filesystem::path& file);

}  // namespace modeflow::preview
