#include "engine/output/RunFolder.h"

#include <cerrno>
#include <cstring>
#include <string_view>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

bool allDigits(std::string_view text) {
    return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

/// NAME_<digits>.vdb, .ply or .png, NAME_contact.png, NAME.resume.
bool isRunFile(const std::string& file, const std::string& scene) {
    if (file == scene + ".resume" || file == scene + "_contact.png") return true;
    const std::string prefix = scene + "_";
    if (file.size() <= prefix.size() + 4 || file.compare(0, prefix.size(), prefix) != 0)
        return false;
    std::string_view rest = std::string_view(file).substr(prefix.size());
    const std::string_view extension = rest.substr(rest.size() - 4);
    // NAME_particles_0001.ply: the particles of a frame.
    constexpr std::string_view particles = "particles_";
    if (extension == ".ply" && rest.substr(0, particles.size()) == particles &&
        rest.size() > particles.size() + 4)
        rest.remove_prefix(particles.size());
    return (extension == ".vdb" || extension == ".ply" || extension == ".png") &&
           allDigits(rest.substr(0, rest.size() - 4));
}

}  // namespace

fs::path RunFolder::lockPath(const fs::path& folder, const std::string& sceneName) {
    return folder / ("." + sceneName + ".lock");
}

RunFolder::RunFolder(fs::path folder, std::string sceneName)
    : mFolder(std::move(folder)), mScene(std::move(sceneName)) {
    std::error_code ec;
    fs::create_directories(mFolder, ec);
    if (ec)
        throw Error("output folder " + mFolder.string() + " cannot be created: " + ec.message());
    const fs::path lock = lockPath(mFolder, mScene);
    mLock = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (mLock < 0)
        throw Error("output folder " + mFolder.string() +
                    " cannot be locked: " + std::strerror(errno));
    if (::flock(mLock, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        char pid[32] = {};
        const ssize_t n = ::pread(mLock, pid, sizeof pid - 1, 0);
        ::close(mLock);
        mLock = -1;
        if (error != EWOULDBLOCK)
            throw Error("output folder " + mFolder.string() +
                        " cannot be locked: " + std::strerror(error));
        const std::string holder = n > 0 && allDigits(std::string_view(pid, std::size_t(n)))
                                       ? " (process " + std::string(pid, std::size_t(n)) + ")"
                                       : "";
        throw Error("another modeflow run" + holder + " is writing " + mScene + " frames into " +
                    mFolder.string() + "; wait for it to finish or choose another --out");
    }
    const std::string self = std::to_string(::getpid());
    if (::ftruncate(mLock, 0) != 0 ||
        ::pwrite(mLock, self.data(), self.size(), 0) != ssize_t(self.size()))
        throw Error("output folder " + mFolder.string() +
                    " cannot be locked: " + std::strerror(errno));
    mStaleRemoved = removeStaleTemporaries(mFolder);
}

RunFolder::~RunFolder() {
    if (mLock >= 0) ::close(mLock);  // releases the lock
}

fs::path RunFolder::checkpointPath() const {
    return mFolder / (mScene + ".resume");
}

int RunFolder::removeEarlierRun() const {
    int removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(mFolder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!isRunFile(it->path().filename().string(), mScene)) continue;
        std::error_code removeError;
        if (fs::remove(it->path(), removeError)) {
            ++removed;
        } else if (removeError) {
            throw Error("cannot remove " + it->path().string() +
                        " of an earlier run: " + removeError.message());
        }
    }
    return removed;
}

}  // namespace modeflow
