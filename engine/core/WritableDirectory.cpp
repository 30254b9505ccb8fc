#include "engine/core/WritableDirectory.h"

#include <unistd.h>
#include <fstream>

#include "engine/core/Error.h"
#include "engine/core/FileKind.h"

namespace modeflow {
namespace {

/// Whether a file can be made in `dir` (made and removed again).
bool takesAFile(const std::filesystem::path& dir) {
    const auto probe = dir / (".write-probe-" + std::to_string(::getpid()));
    std::ofstream out(probe);
    if (!out) return false;
    out.close();
    std::error_code ec;
    std::filesystem::remove(probe, ec);
    return true;
}

}  // namespace

void ensureWritableDirectory(const std::filesystem::path& dir, const std::string& what,
                             const std::string& hint) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec == std::errc::permission_denied)
        if (const auto folder = lockedFolderOn(dir / "probe"))
            throw Error(what + " " + dir.string() +
                        " cannot be reached: permission denied to enter the folder " +
                        folder->string() + hint);
    if (ec || !std::filesystem::is_directory(dir))
        throw Error(what + " " + dir.string() +
                    " cannot be created: " + (ec ? ec.message() : "a file is in the way") + hint);
    if (!takesAFile(dir)) throw Error(what + " " + dir.string() + " is not writable" + hint);
}

void requireWritableFile(const std::filesystem::path& file, const std::string& what) {
    namespace fs = std::filesystem;
    const std::string name = what + " " + file.string() + ": ";
    std::error_code ec;
    if (file.empty() || file.filename().empty() || fs::is_directory(file, ec))
        throw Error(name + "is a folder; name a file");
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    if (const auto locked = lockedFolderOn(folder / "probe"))
        throw Error(name + "permission denied to enter the folder " + locked->string());
    if (!fs::exists(folder, ec))
        throw Error(name + "its folder " + folder.string() + " does not exist");
    if (!fs::is_directory(folder, ec)) throw Error(name + folder.string() + " is not a folder");
    if (!takesAFile(folder))
        throw Error(name + "its folder " + folder.string() + " is not writable");
}

}  // namespace modeflow
