#include "engine/core/AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTemporaryMark = ".tmp-";

std::string failure(std::string_view what, const fs::path& path, const std::string& reason) {
    return "cannot write " + std::string(what) + " " + path.string() + ": " + reason;
}

/// Writes all of `pieces` to a new file; the system's reason on failure.
void writeAll(const fs::path& file, std::span<const std::string_view> pieces, std::string_view what,
              const fs::path& finalPath) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw Error(failure(what, finalPath, std::strerror(errno)));
    for (const std::string_view bytes : pieces) {
        std::size_t done = 0;
        while (done < bytes.size()) {
            const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                const int error = n < 0 ? errno : ENOSPC;
                ::close(fd);
                throw Error(failure(what, finalPath, std::strerror(error)));
            }
            done += std::size_t(n);
        }
    }
    if (::close(fd) != 0) throw Error(failure(what, finalPath, std::strerror(errno)));
}

}  // namespace

fs::path temporaryPathFor(const fs::path& path) {
    fs::path temporary = path;
    temporary += std::string(kTemporaryMark) + std::to_string(::getpid());
    return temporary;
}

void writeFileAtomically(const fs::path& path, std::string_view bytes, std::string_view what) {
    writeFileAtomically(path, {bytes}, what);
}

void writeFileAtomically(const fs::path& path, std::initializer_list<std::string_view> pieces,
                         std::string_view what) {
    writeFileAtomically(path, std::span<const std::string_view>(pieces.begin(), pieces.size()),
                        what);
}

void writeFileAtomically(const fs::path& path, std::span<const std::string_view> pieces,
                         std::string_view what) {
    writeFileAtomically(
        path, what, [&](const fs::path& temporary) { writeAll(temporary, pieces, what, path); });
}

void writeFileAtomically(const fs::path& path, std::string_view what,
                         const std::function<void(const fs::path& temporary)>& write) {
    const fs::path temporary = temporaryPathFor(path);
    try {
        write(temporary);
        std::error_code ec;
        fs::rename(temporary, path, ec);
        if (ec)
            throw Error(failure(
                what, path, "cannot rename " + temporary.string() + " over it: " + ec.message()));
    } catch (...) {
        std::error_code ignored;
        fs::remove(temporary, ignored);  // never leave a partial file behind, whatever failed
        throw;
    }
}

int removeStaleTemporaries(const fs::path& folder) {
    int removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const std::size_t mark = name.rfind(kTemporaryMark);
        if (mark == std::string::npos || mark == 0) continue;
        const std::string digits = name.substr(mark + kTemporaryMark.size());
        if (digits.empty() || digits.size() > 9 ||
            digits.find_first_not_of("0123456789") != std::string::npos)
            continue;
        const pid_t pid = pid_t(std::stol(digits));
        // A process that still runs (or one we may not signal) may still be writing it.
        if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
        std::error_code removeError;
        if (fs::remove(it->path(), removeError)) ++removed;
    }
    return removed;
}

}  // namespace modeflow
