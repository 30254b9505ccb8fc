/// @file EigenMethodTest.cpp
/// `[basis] eigensolver` and the problem's size choose the method (precompute/solve/EigenMethod.h):
/// an explicit choice is kept above the dense limit; `auto` goes from Lanczos to block Lanczos to
/// slicing as the count grows, and slices on several MPI ranks.

#include <gtest/gtest.h>

#include "precompute/solve/EigenMethod.h"

namespace modeflow {
namespace {

constexpr std::int64_t kLarge = 100000;

TEST(EigenMethod, SmallProblemsAreSolvedDenselyWhateverTheChoice) {
    for (const EigensolverChoice choice : {EigensolverChoice::Automatic, EigensolverChoice::Spectra,
                                           EigensolverChoice::Block, EigensolverChoice::Slepc}) {
        EXPECT_EQ(chooseEigenMethod(kDenseLimit, 500, choice, 1), EigenMethod::Dense);
        EXPECT_NE(chooseEigenMethod(kDenseLimit + 1, 500, choice, 1), EigenMethod::Dense);
    }
}

TEST(EigenMethod, AnExplicitChoiceIsKeptAtAnyCountAndRanks) {
    for (const std::int64_t count : {10, 500, 5000})
        for (const int ranks : {1, 4}) {
            EXPECT_EQ(chooseEigenMethod(kLarge, count, EigensolverChoice::Spectra, ranks),
                      EigenMethod::Lanczos);
            EXPECT_EQ(chooseEigenMethod(kLarge, count, EigensolverChoice::Block, ranks),
                      EigenMethod::BlockLanczos);
            EXPECT_EQ(chooseEigenMethod(kLarge, count, EigensolverChoice::Slepc, ranks),
                      EigenMethod::Slicing);
        }
}

TEST(EigenMethod, AutomaticSearchesInBlocksFromSixtyFourUpToAThousandEigenpairs) {
    const auto automatic = [](std::int64_t count, int ranks) {
        return chooseEigenMethod(kLarge, count, EigensolverChoice::Automatic, ranks);
    };
    EXPECT_EQ(automatic(kBlockLanczosFromCount - 1, 1), EigenMethod::Lanczos);
    EXPECT_EQ(automatic(kBlockLanczosFromCount, 1), EigenMethod::BlockLanczos);
    EXPECT_EQ(automatic(300, 1), EigenMethod::BlockLanczos);
    EXPECT_EQ(automatic(1000, 1), EigenMethod::BlockLanczos);
    EXPECT_EQ(automatic(kSlicingFromCount, 1), EigenMethod::Slicing);
    for (const std::int64_t count : {10, 300, 5000})
        EXPECT_EQ(automatic(count, 2), EigenMethod::Slicing) << count;
}

}  // namespace
}  // namespace modeflow
