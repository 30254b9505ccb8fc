/// @file ValidateCommandTest.cpp
/// `modeflow validate`: what it refuses before any study runs — a Python that cannot draw the
/// report (no interpreter, no matplotlib), an unknown study, an --out that cannot be written, a
/// --blender that is no program.
/// The quick report itself: ValidateCommandSlowTest.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

class ValidateCommand : public Cli {
protected:
    /// `modeflow validate --quick --out OUT ARGS` with MODEFLOW_PYTHON=python.
    RunResult validate(const std::string& python, const std::string& args = "") const {
        return runProgram("env MODEFLOW_PYTHON=" + python + " " + testing::cliPath(),
                          "validate --quick --out " + (mDir / "out").string() + " --cache-dir " +
                              mCache.string() + " " + args);
    }
};

TEST_F(ValidateCommand, APythonWithoutMatplotlibIsRefusedBeforeAnyStudy) {
    // A Python whose `import matplotlib` fails, as on a machine without python3-matplotlib.
    fs::create_directories(mDir / "fake" / "matplotlib");
    std::ofstream(mDir / "fake" / "matplotlib" / "__init__.py")
        << "raise ImportError('no matplotlib here')\n";
    const fs::path python = mDir / "python-without-matplotlib";
    std::ofstream(python) << "#!/bin/sh\nPYTHONPATH=" << (mDir / "fake").string()
                          << " exec /usr/bin/python3 \"$@\"\n";
    fs::permissions(python, fs::perms::owner_all);
    const RunResult r = validate(python.string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("modeflow: error: validate: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cannot import matplotlib"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("python3-matplotlib"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("[1/"), std::string::npos) << "a study ran: " << r.err;
    EXPECT_EQ(cacheFiles(), 0);
    EXPECT_FALSE(fs::exists(mDir / "out" / "report.html"));
}

TEST_F(ValidateCommand, AMissingPythonIsRefusedBeforeAnyStudy) {
    const RunResult r = validate((mDir / "no-such-python").string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("cannot start Python"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("MODEFLOW_PYTHON"), std::string::npos) << r.err;
    EXPECT_EQ(cacheFiles(), 0);
}

TEST_F(ValidateCommand, AnUnknownStudyIsNamedWithTheStudiesThereAre) {
    const RunResult r = validate("/usr/bin/python3", "--only integrators,turbulence");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("--only: no study named \"turbulence\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("convergence, integrators"), std::string::npos) << r.err;
}

TEST_F(ValidateCommand, AnEmptyStudyListIsRefusedNamingTheStudies) {
    for (const std::string only : {"\"\"", "\",\"", "integrators,", "\" , \""}) {
        const RunResult r = validate("/usr/bin/python3", "--only " + only);
        EXPECT_EQ(r.status, 1) << only << ": " << r.err;
        EXPECT_NE(r.err.find("an empty study name (studies: convergence, integrators"),
                  std::string::npos)
            << only << ": " << r.err;
        EXPECT_EQ(r.err.find("[1/"), std::string::npos) << "a study ran: " << r.err;
        EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
    }
    // Spaces around a name are no part of it.
    const RunResult unknown = validate("/usr/bin/python3", "--only \" integrators , turbulence\"");
    EXPECT_NE(unknown.err.find("no study named \"turbulence\""), std::string::npos) << unknown.err;
}

TEST_F(ValidateCommand, AReportThatCannotBeWrittenLeavesNoPartialFigureAndSaysSoInOneLine) {
    // The report's Python under a file size limit, as a full disk: results.json (written by
    // modeflow itself) is whole, the first figure cannot be.
    const fs::path python = mDir / "python-with-a-full-disk";
    std::ofstream(python) << "#!/bin/sh\ntrap '' XFSZ\nulimit -f 4\nexec /usr/bin/python3 \"$@\"\n";
    fs::permissions(python, fs::perms::owner_all);
    const RunResult r = validate(python.string(), "--only integrators");
    EXPECT_EQ(r.status, 1) << r.err;
    const std::string line =
        "modeflow: error: validate: the report could not be written: cannot "
        "write " +
        (mDir / "out" / "figures" / "integrators.png").string() + ": File too large\n";
    EXPECT_NE(r.err.find(line), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("report.py"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(mDir / "out" / "results.json"));
    EXPECT_FALSE(fs::exists(mDir / "out" / "report.html"));
    for (const auto& entry : fs::directory_iterator(mDir / "out" / "figures"))
        ADD_FAILURE() << "left behind: " << entry.path();
}

TEST_F(ValidateCommand, ABlenderThatIsNoProgramIsRefusedBeforeAnyStudy) {
    const RunResult r =
        validate("/usr/bin/python3", "--blender " + (mDir / "no-such-blender").string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("--blender: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is not an executable file"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("[1/"), std::string::npos) << "a study ran: " << r.err;
}

TEST_F(ValidateCommand, AnOutputFolderThatCannotBeWrittenIsRefused) {
    std::ofstream(mDir / "file") << "not a folder";
    const RunResult r = runProgram(testing::cliPath(),
                                   "validate --quick --out " + (mDir / "file" / "out").string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("cannot be created: Not a directory; choose another folder with --out"),
              std::string::npos)
        << r.err;
}

TEST_F(ValidateCommand, OneStudyWritesItsResultsAndAReportWithItsFigure) {
    const RunResult r = validate("/usr/bin/python3", "--only integrators");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("validate: [1/1] integrators: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("validate: integrators done in "), std::string::npos) << r.err;
    EXPECT_EQ(r.out, (mDir / "out" / "report.html").string() + "\n");
    const std::string html = testing::slurp(mDir / "out" / "report.html");
    EXPECT_NE(html.find("src='data:image/png;base64,iVBOR"), std::string::npos) << "no PNG inline";
    EXPECT_TRUE(fs::exists(mDir / "out" / "figures" / "integrators.png"));
    EXPECT_NE(testing::slurp(mDir / "out" / "results.json").find("\"integrators\""),
              std::string::npos);
}

}  // namespace
}  // namespace modeflow
