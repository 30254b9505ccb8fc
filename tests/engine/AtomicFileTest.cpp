/// AtomicFile: a file is replaced whole or not at all, errors carry the system's reason, and
/// temporaries of processes that are gone are swept away while those of live ones stay.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class AtomicFileTest : public ::testing::Test {
protected:
    int entries() const {
        return int(std::distance(fs::directory_iterator(mFolder), fs::directory_iterator()));
    }
    testing::TestFolder mFolder;
};

TEST_F(AtomicFileTest, WritesAndReplacesWholeFiles) {
    const fs::path file = mFolder / "a.bin";
    writeFileAtomically(file, "first", "test file");
    EXPECT_EQ(contents(file), "first");
    writeFileAtomically(file, std::string(100000, 'x'), "test file");
    EXPECT_EQ(contents(file), std::string(100000, 'x'));
    EXPECT_EQ(entries(), 1);
    writeFileAtomically(file, {"head|", std::string(70000, 'p'), "", "|sum"}, "test file");
    EXPECT_EQ(contents(file), "head|" + std::string(70000, 'p') + "|sum");
    EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFileTest, AFailedWriteKeepsTheOldFileAndSaysWhy) {
    const fs::path file = mFolder / "a.bin";
    writeFileAtomically(file, "old", "test file");
    // A file size limit makes write() fail with EFBIG part way, as a full disk fails it.
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{1000, 1000};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            writeFileAtomically(file, std::string(5000, 'n'), "test file");
        } catch (const Error& e) {
            const std::string message = e.what();
            const bool named =
                message.find("cannot write test file " + file.string()) != std::string::npos;
            const bool reason = message.find("File too large") != std::string::npos;
            ::_exit(named && reason ? 0 : 2);
        }
        ::_exit(3);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "2: the message lacks the file or the reason, 3: no error";
    EXPECT_EQ(contents(file), "old");
    EXPECT_EQ(entries(), 1) << "a temporary was left behind";
}

TEST_F(AtomicFileTest, AWriterThatThrowsLeavesNoTemporary) {
    const fs::path file = mFolder / "frame.vdb";
    EXPECT_THROW(writeFileAtomically(file, "frame",
                                     [](const fs::path& temporary) {
                                         std::ofstream(temporary) << "partial";
                                         throw Error("encoder failed");
                                     }),
                 Error);
    EXPECT_EQ(entries(), 0);
}

TEST_F(AtomicFileTest, StaleTemporariesOfGoneProcessesAreRemovedOthersKept) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);  // its pid is now free: the process is gone
    const fs::path stale = mFolder / ("frame_0007.vdb.tmp-" + std::to_string(child));
    const fs::path mine = temporaryPathFor(mFolder / "frame_0008.vdb");
    const fs::path parent = mFolder / ("frame_0009.vdb.tmp-" + std::to_string(::getppid()));
    const fs::path unrelated = mFolder / "notes.tmp-backup";
    for (const fs::path& f : {stale, mine, parent, unrelated}) std::ofstream(f) << "x";
    EXPECT_EQ(removeStaleTemporaries(mFolder), 1);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(mine));
    EXPECT_TRUE(fs::exists(parent));
    EXPECT_TRUE(fs::exists(unrelated));
    EXPECT_EQ(removeStaleTemporaries(mFolder / "missing"), 0);
}

}  // namespace
}  // namespace modeflow
