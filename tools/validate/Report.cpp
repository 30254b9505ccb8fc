#include "tools/validate/Report.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "engine/core/Error.h"

namespace modeflow::validate {

extern const char kReportScript[];

namespace {

/// report.py's exit status when matplotlib cannot be imported.
constexpr int kNoMatplotlib = 3;
/// The child's status when the interpreter cannot be started.
constexpr int kNoInterpreter = 127;

/// report.py's exit status when a file of the report cannot be written: its last line says which.
constexpr int kWriteFailed = 4;

struct ScriptResult {
    int status = 0;
    std::string errors;  ///< what the script wrote to its standard error
};

/// The last line of `text` that is not empty.
std::string lastLine(const std::string& text) {
    std::size_t end = text.find_last_not_of("\n");
    if (end == std::string::npos) return "";
    const std::size_t begin = text.rfind('\n', end);
    return text.substr(begin == std::string::npos ? 0 : begin + 1,
                       end - (begin == std::string::npos ? 0 : begin + 1) + 1);
}

/// Runs `interpreter - args...` with the report script on its standard input; its standard
/// output goes to ours, its standard error is returned (Python reads the whole script before it
/// runs any of it, so nothing it writes there can stall the script's writing).
ScriptResult runScript(const std::vector<std::string>& args) {
    const std::string interpreter = reportInterpreter();
    int pipeFds[2], errorFds[2];
    if (pipe(pipeFds) != 0)
        throw Error(std::string("report: cannot create a pipe: ") + std::strerror(errno));
    if (pipe(errorFds) != 0) {
        close(pipeFds[0]);
        close(pipeFds[1]);
        throw Error(std::string("report: cannot create a pipe: ") + std::strerror(errno));
    }
    const pid_t pid = fork();
    if (pid < 0) throw Error(std::string("report: cannot start Python: ") + std::strerror(errno));
    if (pid == 0) {
        dup2(pipeFds[0], STDIN_FILENO);
        dup2(errorFds[1], STDERR_FILENO);
        close(pipeFds[0]);
        close(pipeFds[1]);
        close(errorFds[0]);
        close(errorFds[1]);
        std::vector<char*> argv{const_cast<char*>(interpreter.c_str()), const_cast<char*>("-")};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execvp(argv[0], argv.data());
        _exit(kNoInterpreter);
    }
    close(pipeFds[0]);
    close(errorFds[1]);
    // An interpreter that never started (or exited early) closes the pipe: the write must fail
    // with EPIPE, not kill this process with SIGPIPE.
    struct sigaction ignore {
    }, previous{};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous);
    const char* text = kReportScript;
    std::size_t left = std::strlen(text);
    while (left > 0) {
        const ssize_t n = write(pipeFds[1], text, left);
        if (n <= 0) break;  // the interpreter stopped reading; its status says why
        text += n, left -= std::size_t(n);
    }
    close(pipeFds[1]);
    sigaction(SIGPIPE, &previous, nullptr);
    ScriptResult result;
    char buffer[4096];
    for (;;) {
        const ssize_t n = read(errorFds[0], buffer, sizeof buffer);
        if (n > 0)
            result.errors.append(buffer, std::size_t(n));
        else if (n == 0 || errno != EINTR)
            break;
    }
    close(errorFds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

}  // namespace

std::string reportInterpreter() {
    if (const char* chosen = std::getenv("MODEFLOW_PYTHON"); chosen && *chosen) return chosen;
    if (access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
    return "python3";
}

void requirePlotting() {
    const ScriptResult check = runScript({"--check"});
    std::cerr << check.errors;
    const int status = check.status;
    if (status == kNoInterpreter)
        throw Error("validate: cannot start Python (" + reportInterpreter() +
                    ") to draw the report: install python3 and python3-matplotlib "
                    "(tools/install-deps.sh), or "
                    "set MODEFLOW_PYTHON to a Python with matplotlib");
    if (status == kNoMatplotlib)
        throw Error("validate: " + reportInterpreter() +
                    " cannot import matplotlib, which draws the report's figures: install "
                    "python3-matplotlib "
                    "(tools/install-deps.sh), or set MODEFLOW_PYTHON to a Python with matplotlib");
    if (status != 0)
        throw Error("validate: the report script's check failed in " + reportInterpreter() +
                    " (exit status " + std::to_string(status) + ")");
}

void drawReport(const std::filesystem::path& dir) {
    const ScriptResult drawn = runScript({dir.string()});
    if (drawn.status == kWriteFailed) {
        // One line: which file, and why (its partial file is gone, no figure is left half written).
        std::string why = lastLine(drawn.errors);
        if (why.rfind("report.py: ", 0) == 0) why.erase(0, 11);
        throw Error("validate: the report could not be written: " + why);
    }
    std::cerr << drawn.errors;
    if (drawn.status != 0)
        throw Error("validate: drawing the report from " + (dir / "results.json").string() +
                    " failed (" + reportInterpreter() + " exit status " +
                    std::to_string(drawn.status) + ", its messages above)");
}

}  // namespace modeflow::validate
