#include "tools/validate/Report.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "engine/core/Error.h"

namespace modeflow::validate {

extern const char kReportScript[];

namespace {

/// report.py's exit status when matplotlib cannot be imported.
constexpr int kNoMatplotlib = 3;
/// The child's status when the interpreter cannot be started.
constexpr int kNoInterpreter = 127;

/// Runs `interpreter - args...` with the report script on its standard input; its output goes
/// to ours. Returns its exit status.
int runScript(const std::vector<std::string>& args) {
    const std::string interpreter = reportInterpreter();
    int pipeFds[2];
    if (pipe(pipeFds) != 0)
        throw Error(std::string("report: cannot create a pipe: ") + std::strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) throw Error(std::string("report: cannot start Python: ") + std::strerror(errno));
    if (pid == 0) {
        dup2(pipeFds[0], STDIN_FILENO);
        close(pipeFds[0]);
        close(pipeFds[1]);
        std::vector<char*> argv{const_cast<char*>(interpreter.c_str()), const_cast<char*>("-")};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execvp(argv[0], argv.data());
        _exit(kNoInterpreter);
    }
    close(pipeFds[0]);
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
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

std::string reportInterpreter() {
    if (const char* chosen = std::getenv("MODEFLOW_PYTHON"); chosen && *chosen) return chosen;
    if (access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
    return "python3";
}

void requirePlotting() {
    const int status = runScript({"--check"});
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
    const int status = runScript({dir.string()});
    if (status != 0)
        throw Error("validate: drawing the report from " + (dir / "results.json").string() +
                    " failed (" + reportInterpreter() + " exit status " + std::to_string(status) +
                    ", its messages above)");
}

}  // namespace modeflow::validate
