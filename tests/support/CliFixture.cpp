#include "tests/support/CliFixture.h"

#include <cstdlib>
#include <fstream>
#include <iterator>

#include <sys/wait.h>

namespace modeflow::testing {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string cliPath() {
    return MODEFLOW_CLI;
}

RunResult Cli::runProgram(const std::string& program, const std::string& args) const {
    const fs::path out = mDir / "stdout.txt", err = mDir / "stderr.txt";
    const std::string cmd = "env -u MODEFLOW_CACHE_DIR " + program + " " + args + " >" +
                            out.string() + " 2>" + err.string() + " </dev/null";
    const int raw = std::system(cmd.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

fs::path Cli::scene(const std::string& name, const std::string& text) const {
    const fs::path p = mDir / name;
    std::ofstream(p) << text;
    return p;
}

std::string Cli::precompute(const fs::path& s, const std::string& extra) const {
    return "precompute " + s.string() + " --cache-dir " + mCache.string() + " " + extra;
}

int Cli::cacheFiles() const {
    if (!fs::exists(mCache)) return 0;
    int n = 0;
    for (const auto& e : fs::directory_iterator(mCache)) n += e.is_regular_file();
    return n;
}

void Cli::expectRejected(const std::string& args, const std::string& needle) const {
    const RunResult r = run(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "stderr: " << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << "stderr: " << r.err;
    EXPECT_EQ(cacheFiles(), 0) << args;
}

}  // namespace modeflow::testing
