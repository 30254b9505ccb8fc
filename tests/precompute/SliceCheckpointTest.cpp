// A sliced eigensolve keeps each finished interval beside its cache (SliceCheckpoint.h); a rerun
// reads the intervals an interrupted run kept instead of solving them, gets the pairs an
// uninterrupted run gets, and solves again any interval whose file is damaged or foreign.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>

#include "precompute/solve/SliceCheckpoint.h"
#include "precompute/solve/SlicedEigensolver.h"
#include "tests/support/ChainLaplacian.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

constexpr int kRows = 2000, kCount = 90;
const double kMass = 1.0 / (kRows + 1);

/// The solve of the chain's lowest kCount pairs, its intervals kept for `cache`, its notes kept in
/// `notes`. The estimate is far too low on purpose: several intervals.
EigenPairs solve(const fs::path& cache, std::vector<std::string>& notes) {
    EigenRequest request{kCount, -1.0, 1e-12, "test eigensolve", {}, false};
    request.spectralDimension = 1;
    const double s = std::sin(kCount * M_PI * kMass / 2.0);
    request.estimate = 0.3 * 4.0 * s * s / (kMass * kMass);
    request.checkpoints = {cache, [&notes](const std::string& m) { notes.push_back(m); }};
    return slicedEigenpairs(testing::chainLaplacian(kRows), Eigen::VectorXd::Constant(kRows, kMass),
                            request);
}

std::vector<fs::path> checkpointFiles(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(folder))
        if (e.path().extension() == ".mfslice") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// The file of interval `index` among `files` (named <cache>.<problem>.<index>.mfslice).
fs::path intervalFile(const std::vector<fs::path>& files, int index) {
    for (const fs::path& f : files)
        if (f.stem().extension().string().substr(1) == std::to_string(index)) return f;
    ADD_FAILURE() << "no checkpoint of interval " << index;
    return {};
}

/// Largest relative eigenvalue difference, and largest 1 − |aᵢᵀ M bᵢ| (the eigenvalues are simple).
void expectSamePairs(const EigenPairs& a, const EigenPairs& b) {
    ASSERT_EQ(a.values.size(), b.values.size());
    const double values = ((a.values - b.values).cwiseQuotient(a.values)).cwiseAbs().maxCoeff();
    EXPECT_LE(values, 1e-12) << "largest relative eigenvalue difference";
    double vectors = 0.0;
    for (Eigen::Index j = 0; j < a.values.size(); ++j)
        vectors = std::max(vectors, 1.0 - std::abs(kMass * a.vectors.col(j).dot(b.vectors.col(j))));
    EXPECT_LE(vectors, 1e-10) << "largest 1 - |cos| between the two runs' vectors";
}

bool said(const std::vector<std::string>& notes, const std::string& part) {
    for (const std::string& n : notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

std::string joined(const std::vector<std::string>& notes) {
    std::string all;
    for (const std::string& n : notes) all += n + "\n";
    return all;
}

TEST(SliceCheckpoint, InterruptedSolveResumesFromTheIntervalsItKept) {
    const testing::TestFolder folder;
    const fs::path cache = folder / "0123456789abcdef.mfbasis";
    std::vector<std::string> notes;
    const EigenPairs whole = solve(cache, notes);
    EXPECT_TRUE(notes.empty()) << joined(notes);
    const std::vector<fs::path> files = checkpointFiles(folder);
    ASSERT_GE(files.size(), 2u) << "intervals kept";
    // What a run killed during its second interval leaves: the first interval's file.
    for (size_t i = 1; i < files.size(); ++i) fs::remove(intervalFile(files, int(i)));

    const EigenPairs resumed = solve(cache, notes);
    EXPECT_TRUE(said(notes, "test eigensolve: 1 of " + std::to_string(files.size()) +
                                " intervals from an interrupted run"))
        << joined(notes);
    EXPECT_LT(resumed.stats.factorizations, whole.stats.factorizations)
        << "the kept interval was solved again";
    expectSamePairs(whole, resumed);
    EXPECT_EQ(checkpointFiles(folder).size(), files.size()) << "the solved intervals are kept";

    EXPECT_EQ(removeSliceCheckpoints(cache), int(files.size()));
    EXPECT_TRUE(checkpointFiles(folder).empty());
}

TEST(SliceCheckpoint, DamagedOrForeignCheckpointIsSolvedAgain) {
    const testing::TestFolder folder;
    const fs::path cache = folder / "0123456789abcdef.mfbasis";
    std::vector<std::string> notes;
    const EigenPairs whole = solve(cache, notes);
    const std::vector<fs::path> files = checkpointFiles(folder);
    ASSERT_GE(files.size(), 2u);
    const fs::path first = intervalFile(files, 0), second = intervalFile(files, 1);
    const auto flipByte = [&] {
        std::fstream f(first, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(std::streamoff(fs::file_size(first) / 2));
        const char c = char(f.get());
        f.seekp(std::streamoff(fs::file_size(first) / 2));
        f.put(char(c ^ 0x10));
    };
    const auto truncate = [&] { fs::resize_file(first, fs::file_size(first) - 100); };
    const auto otherInterval = [&] {
        fs::copy_file(second, first, fs::copy_options::overwrite_existing);
    };
    const std::pair<std::function<void()>, std::string> damages[] = {
        {flipByte, "damaged (checksum mismatch)"},
        {truncate, "truncated or corrupt"},
        {otherInterval, "of another eigenproblem or interval"}};
    for (const auto& [damage, complaint] : damages) {
        damage();
        notes.clear();
        const EigenPairs again = solve(cache, notes);
        EXPECT_TRUE(said(notes, "test eigensolve: eigensolver checkpoint " + first.string() +
                                    " is " + complaint))
            << joined(notes);
        EXPECT_TRUE(said(notes, "; solving it again")) << joined(notes);
        EXPECT_TRUE(said(notes, std::to_string(files.size() - 1) + " of " +
                                    std::to_string(files.size()) + " intervals"))
            << joined(notes);
        expectSamePairs(whole, again);
    }
}

TEST(SliceCheckpoint, OnlyTheCachesOwnCheckpointsAreRemoved) {
    const testing::TestFolder folder;
    for (const char* name : {"aaaaaaaaaaaaaaaa.0123.0.mfslice", "aaaaaaaaaaaaaaaa.0123.1.mfslice",
                             "bbbbbbbbbbbbbbbb.0123.0.mfslice", "aaaaaaaaaaaaaaaa.mfbasis"})
        std::ofstream(folder / name) << "x";
    EXPECT_EQ(removeSliceCheckpoints(folder / "aaaaaaaaaaaaaaaa.mfbasis"), 2);
    EXPECT_TRUE(fs::exists(folder / "bbbbbbbbbbbbbbbb.0123.0.mfslice"));
    EXPECT_TRUE(fs::exists(folder / "aaaaaaaaaaaaaaaa.mfbasis"));
}

}  // namespace
}  // namespace modeflow
