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
/// be reached: permission denied to enter the folder /a/b" (a folder on the way that cannot be
/// entered), "cannot be examined (reason)", ...; nothing when it is a regular file. Symbolic links
/// are followed.
std::optional<std::string> whyNotARegularFile(const std::filesystem::path& path);

/// The first folder on the way to `path` (its parent folders, from the root or the working
/// folder down) that this process may not enter, if any.
std::optional<std::filesystem::path> lockedFolderOn(const std::filesystem::path& path);

}  // namespace modeflow
