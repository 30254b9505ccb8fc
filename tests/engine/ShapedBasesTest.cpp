/// The shaped bases `modeflow stir` switches between: leading ranges of the scene's basis.

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/dynamics/ShapedBases.h"
#include "tests/support/RandomCoefficients.h"

namespace modeflow {
namespace {

TEST(ShapedBasesTest, OneBasisPerLeadingRange) {
    BasisSpec spec;
    spec.velocityModes = {{1, 10}, {391, 400}, {501, 505}};
    const auto bases = shapedBases(spec);
    ASSERT_EQ(bases.size(), 3u);
    EXPECT_EQ(bases[0].label, "1-10");
    EXPECT_EQ(bases[0].modes, 10);
    EXPECT_EQ(bases[1].label, "1-10,391-400");
    EXPECT_EQ(bases[1].modes, 20);
    EXPECT_EQ(bases[2].modes, 25);
    spec.velocityModes = {{1, 40}};
    EXPECT_EQ(shapedBases(spec).size(), 1u);
}

TEST(ShapedBasesTest, LeadingCoefficientsAreTheGalerkinSystemOfTheLeadingModes) {
    const auto full = testing::randomDense(9, 3);
    const auto leading = leadingCoefficients(full, 5);
    ASSERT_EQ(leading->size(), 5);
    for (int k = 0; k < 5; ++k)
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j) EXPECT_EQ(leading->entry(k, i, j), full.entry(k, i, j));
    EXPECT_THROW(leadingCoefficients(full, 10), Error);
}

TEST(ShapedBasesTest, LeadingModesKeepTheFirstColumns) {
    BasisCache cache;
    cache.velocity.modes = Eigen::MatrixXd::Random(30, 6);
    cache.velocity.eigenvalues = Eigen::VectorXd::LinSpaced(6, 1.0, 6.0);
    cache.velocity.modeNumbers = {1, 2, 3, 7, 8, 9};
    const BasisCache leading = leadingModes(cache, 3);
    EXPECT_EQ(leading.velocity.modes, cache.velocity.modes.leftCols(3));
    EXPECT_EQ(leading.velocity.eigenvalues, cache.velocity.eigenvalues.head(3));
    EXPECT_EQ(leading.velocity.modeNumbers, (std::vector<int>{1, 2, 3}));
    EXPECT_THROW(leadingModes(cache, 0), Error);
}

}  // namespace
}  // namespace modeflow
