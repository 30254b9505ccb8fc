#include "tools/validate/MantaflowPlume.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "engine/core/Error.h"

namespace modeflow::validate {

extern const char kMantaflowPlumeScript[];

namespace {

namespace fs = std::filesystem;

bool isExecutableFile(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error) && access(path.c_str(), X_OK) == 0;
}

/// A fresh folder under the system's temporary folder, removed with its files on destruction.
class ScratchFolder {
public:
    ScratchFolder() {
        std::string pattern = (fs::temp_directory_path() / "modeflow-mantaflow-XXXXXX").string();
        if (!mkdtemp(pattern.data()))
            throw Error("mantaflow: cannot create a temporary folder in " +
                        fs::temp_directory_path().string() + ": " + std::strerror(errno));
        mPath = pattern;
    }
    ~ScratchFolder() {
        std::error_code ignored;
        fs::remove_all(mPath, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

/// Runs `argv` with its standard output sent to our standard error (Blender talks on stdout,
/// and `modeflow validate`'s stdout is the report's path alone); returns its exit status.
int runToStderr(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0)
        throw Error(std::string("mantaflow: cannot start Blender: ") + std::strerror(errno));
    if (pid == 0) {
        dup2(STDERR_FILENO, STDOUT_FILENO);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

BlenderChoice findBlender(const std::optional<std::string>& requested) {
    if (requested) {
        if (!isExecutableFile(*requested))
            throw Error("--blender: " + *requested + " is not an executable file");
        return {fs::absolute(*requested), ""};
    }
    const char* path = std::getenv("PATH");
    std::stringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');)
        if (!folder.empty() && isExecutableFile(fs::path(folder) / "blender"))
            return {fs::path(folder) / "blender", ""};
    return {{},
            "no `blender` on the PATH (install Debian's blender package, or give --blender PATH)"};
}

nlohmann::json runMantaflowPlume(const fs::path& blender, int resolution, int frames) {
    const ScratchFolder scratch;
    const fs::path out = scratch.path() / "plume.json";
    const int status =
        runToStderr({blender.string(), "-b", "--factory-startup", "--python-exit-code", "1",
                     "--python-expr", kMantaflowPlumeScript, "--", "--out", out.string(),
                     "--resolution", std::to_string(resolution), "--frames", std::to_string(frames),
                     "--cache", (scratch.path() / "cache").string()});
    if (status == 127) throw Error("mantaflow: cannot start " + blender.string());
    if (status != 0)
        throw Error("mantaflow: " + blender.string() + " exited with status " +
                    std::to_string(status) + " running mantaflow_plume.py (its messages above)");
    std::ifstream file(out);
    if (!file)
        throw Error("mantaflow: " + blender.string() + " wrote no " + out.filename().string() +
                    " (its messages above)");
    try {
        return nlohmann::json::parse(file);
    } catch (const nlohmann::json::exception& e) {
        throw Error("mantaflow: the result of mantaflow_plume.py is not JSON: " +
                    std::string(e.what()));
    }
}

}  // namespace modeflow::validate
