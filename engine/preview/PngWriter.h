#pragma once
/// @file PngWriter.h
/// Images to PNG files (stb_image_write), written atomically like the cache and VDB frames: into
/// a temporary file in the same folder, renamed over the target once complete, so a viewer that
/// watches the folder never opens half a picture.

#include <filesystem>

#include "engine/preview/Image.h"

namespace modeflow::preview {

/// Writes `image` to `file` as an 8-bit RGBA PNG: into `file` + ".tmp-<pid>", then renamed over
/// `file`. On failure the temporary file is removed and an existing `file` is left as it was.
/// @throw modeflow::Error naming `file` when the image is empty or its byte count does not match
///        its size, the encoder fails, the folder is missing or not writable, or the disk is full.
void writePng(const std::filesystem::path& file, const Image& image);

}  // namespace modeflow::preview
