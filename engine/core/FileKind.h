#pragma once
/// @file FileKind.h
/// Input files are checked before they are opened: a directory cannot be read, a device such as
/// /dev/zero never ends, and opening a FIFO waits for a writer. The message says what the path is.

#include <filesystem>
#include <optional>
#include <string>

namespace modeflow {

/// Why `path` cannot be read as a file, in words that follow its name: "does not exist", "is a
/// directory", "is a character device", "is a block device", "is a FIFO", "is a socket", "cannot
/// be examined (Permission denied)", ...; nothing when it is a regular file. Symbolic links are
/// followed.
std::optional<std::string> whyNotARegularFile(const std::filesystem::path& path);

}  // namespace modeflow
