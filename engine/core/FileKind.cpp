/// @file FileKind.cpp

#include "engine/core/FileKind.h"

#include <cerrno>
#include <system_error>

#include <unistd.h>

namespace modeflow {

std::optional<std::filesystem::path> lockedFolderOn(const std::filesystem::path& path) {
    std::filesystem::path prefix;
    const std::filesystem::path whole =
        path.is_absolute() ? path : std::filesystem::path(".") / path;
    for (const std::filesystem::path& part : whole.parent_path()) {
        prefix /= part;
        if (::access(prefix.c_str(), X_OK) != 0 && errno == EACCES) return prefix;
    }
    return std::nullopt;
}

std::optional<std::string> whyNotARegularFile(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    switch (fs::status(path, ec).type()) {
        case fs::file_type::regular:
            return std::nullopt;
        case fs::file_type::not_found:
            return "does not exist";
        case fs::file_type::none:  // stat failed for another reason, e.g. a folder not searchable
            if (ec == std::errc::permission_denied)
                if (const auto folder = lockedFolderOn(path))
                    return "cannot be reached: permission denied to enter the folder " +
                           folder->string();
            return "cannot be examined (" + ec.message() + ")";
        case fs::file_type::directory:
            return "is a directory";
        case fs::file_type::character:
            return "is a character device";
        case fs::file_type::block:
            return "is a block device";
        case fs::file_type::fifo:
            return "is a FIFO";
        case fs::file_type::socket:
            return "is a socket";
        default:
            return "is not a regular file";
    }
}

}  // namespace modeflow
