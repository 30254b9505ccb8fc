#include "engine/core/WritableDirectory.h"

#include <unistd.h>
#include <fstream>

#include "engine/core/Error.h"

namespace modeflow {

void ensureWritableDirectory(const std::filesystem::path& dir, const std::string& what,
                             const std::string& hint) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw Error(what + " " + dir.string() +
                    " cannot be created: " + (ec ? ec.message() : "a file is in the way") + hint);
    const auto probe = dir / (".write-probe-" + std::to_string(::getpid()));
    std::ofstream out(probe);
    if (!out) throw Error(what + " " + dir.string() + " is not writable" + hint);
    out.close();
    std::filesystem::remove(probe, ec);
}

}  // namespace modeflow
