/// @file FileKind.cpp

#include "engine/core/FileKind.h"

#include <system_error>

namespace modeflow {

std::optional<std::string> whyNotARegularFile(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    switch (fs::status(path, ec).type()) {
        case fs::file_type::regular:
            return std::nullopt;
        case fs::file_type::not_found:
            return "does not exist";
        case fs::file_type::none:  // stat failed for another reason, e.g. a folder not searchable
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
