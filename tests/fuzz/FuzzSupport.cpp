#include "tests/fuzz/FuzzSupport.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "engine/core/Error.h"
#include "engine/core/PrintableText.h"

namespace modeflow::fuzz {
namespace {

/// The scratch folder, removed when the process exits normally.
class ScratchFolder {
public:
    ScratchFolder()
        : mPath(std::filesystem::temp_directory_path() /
                ("modeflow-fuzz-" + std::to_string(::getpid()))) {
        std::filesystem::create_directories(mPath);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(mPath, ignored);
    }
    const std::filesystem::path& path() const { return mPath; }

private:
    std::filesystem::path mPath;
};

std::string& lastMessage() {
    static std::string message;
    return message;
}

}  // namespace

void require(bool condition, const std::string& what) {
    if (!condition) throw FuzzFinding(what);
}

bool acceptedOrRefused(const std::function<void()>& read) {
    try {
        read();
        return true;
    } catch (const Error& e) {
        const std::string_view message = e.what();
        require(!message.empty() && message.size() <= 4096 &&
                    printableText(message, std::string_view::npos) == message,
                "a refusal's message is empty, longer than 4 KiB or not printable text: " +
                    printableText(message, 200));
        lastMessage() = message;
        return false;
    }
}

const std::string& lastRefusal() {
    return lastMessage();
}

std::filesystem::path scratchFile(const std::string& name, std::string_view bytes) {
    static const ScratchFolder folder;
    const std::filesystem::path path = folder.path() / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(bytes.size()));
    return path;
}

}  // namespace modeflow::fuzz
