#pragma once
/// @file InputFile.h
/// Checks before modeflow reads a file a user named (a cache, a checkpoint, an input script), so
/// that a wrong name fails at once with a message instead of hanging or exhausting memory: a
/// folder, a FIFO or a device (/dev/zero never ends) is refused, and so is a file larger than its
/// kind can be.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace modeflow {

/// The size of `path` in bytes, after checking that it is a regular file (symbolic links
/// followed) of at most `maxBytes`. `what` names the kind of file in messages ("input script").
/// @throw Error "<what> <path> ..." when it is missing, a folder, another non-regular file or too
///        large.
std::uintmax_t regularFileSize(const std::filesystem::path& path, std::string_view what,
                               std::uintmax_t maxBytes);

/// The whole contents of `path` (binary), with regularFileSize's checks; a file that grows
/// while it is read is refused too.
/// @throw Error as regularFileSize, or when reading fails.
std::string readRegularFile(const std::filesystem::path& path, std::string_view what,
                            std::uintmax_t maxBytes);

}  // namespace modeflow
