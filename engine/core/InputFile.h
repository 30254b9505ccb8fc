#pragma once
/// @file InputFile.h
/// Files a user names (a scene, a cache, a checkpoint, an input script), checked before they are
/// read so that a wrong name fails at once with a message instead of hanging or filling memory:
/// a directory, a FIFO or a device (/dev/zero never ends) is refused, and so is a file larger
/// than its kind can be. Each message begins with the path and names the kind of file.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace modeflow {

/// The size of `path` after checking that it is a regular file (symbolic links followed) of at
/// most `maxBytes`; `what` names its kind ("scene file", "input script").
/// @throw Error "PATH: no such input script", "PATH: is a directory, not a scene file" (and so
///        on for the other kinds of path, FileKind.h), or inputTooLarge's message.
std::uintmax_t inputFileSize(const std::filesystem::path& path, std::string_view what,
                             std::uintmax_t maxBytes);

/// The whole of `path` (binary), after inputFileSize's checks, read in pieces up to `maxBytes`:
/// a file that grows while it is read is refused too.
/// @throw Error as inputFileSize, or "PATH: cannot open the WHAT (reason)" / "PATH: error while
///        reading the WHAT".
std::string readInputFile(const std::filesystem::path& path, std::string_view what,
                          std::uintmax_t maxBytes);

/// "NAME: 5000000 bytes is too large for a scene file (at most 4 MiB); is it the right file?"
std::string inputTooLarge(const std::string& name, std::uintmax_t bytes, std::string_view what,
                          std::uintmax_t maxBytes);

}  // namespace modeflow
