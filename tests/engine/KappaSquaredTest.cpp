/// @file KappaSquaredTest.cpp
/// κ² lists as every consumer takes them: a harmonic mode's round-off (±1e-11) is exactly 0,
/// a clearly negative κ² (−1e-3) is refused, in the check itself and in the systems built on it.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/core/KappaSquared.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "tests/support/RandomCoefficients.h"

namespace modeflow {
namespace {

/// An annulus-like spectrum: one harmonic mode (κ² given), then 2.9, 6.3, 11.
Eigen::VectorXd spectrumWithHarmonic(double harmonic) {
    Eigen::VectorXd k2(4);
    k2 << harmonic, 2.9, 6.3, 11.0;
    return k2;
}

std::string refusal(const Eigen::VectorXd& k2) {
    try {
        checkedKappaSquared(k2, "test");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(KappaSquared, HarmonicRoundOffOfEitherSignBecomesExactlyZero) {
    for (const double roundOff : {-1e-11, 1e-11, 0.0}) {
        const Eigen::VectorXd checked = checkedKappaSquared(spectrumWithHarmonic(roundOff), "test");
        EXPECT_EQ(checked[0], 0.0) << "from " << roundOff;
        EXPECT_EQ(checked.tail(3), spectrumWithHarmonic(roundOff).tail(3));
    }
}

TEST(KappaSquared, ClearlyNegativeValuesAreRefusedNamingTheModeAndTolerance) {
    const std::string message = refusal(spectrumWithHarmonic(-1e-3));
    EXPECT_NE(message.find("test: kappa^2 of mode 1 is -0.001, negative beyond round-off"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("1e-06 of the first non-zero kappa^2, 2.9"), std::string::npos)
        << message;
}

TEST(KappaSquared, NonFiniteValuesAreRefused) {
    for (const double bad : {NAN, INFINITY, -INFINITY}) {
        Eigen::VectorXd k2 = spectrumWithHarmonic(0.0);
        k2[2] = bad;
        EXPECT_NE(refusal(k2).find("kappa^2 of mode 3 is"), std::string::npos) << refusal(k2);
    }
}

TEST(KappaSquared, TheFirstNonZeroValueIsFoundInAnyOrder) {
    Eigen::VectorXd shaped(5);
    shaped << 40.0, -2e-11, 7.5, 3e-12, 19.0;  // a frequency-shaped basis: any order
    EXPECT_EQ(firstNonZeroKappaSquared(shaped, shaped.cwiseAbs().maxCoeff()), 7.5);
    const Eigen::VectorXd checked = checkedKappaSquared(shaped, "test");
    EXPECT_EQ(checked[1], 0.0);
    EXPECT_EQ(checked[3], 0.0);
    // With every value harmonic the anchor itself sets the scale.
    EXPECT_EQ(firstNonZeroKappaSquared(Eigen::Vector2d(-1e-11, 1e-11), 2.0), 2.0);
}

TEST(KappaSquared, FluidAndMhdSystemsTakeHarmonicRoundOffAsZeroAndRefuseNegativeValues) {
    const DenseCoefficients c = DenseCoefficients::fromFull(4, testing::randomFullTensor(4, 5));
    const FluidParameters fluid{spectrumWithHarmonic(-1e-11), 0.01, 0.1};
    EXPECT_EQ(FluidSystem::decayRatesOf(fluid, 4)[0], 0.0);
    EXPECT_EQ(FluidSystem::massOf(fluid, 4)[0], 1.0);
    EXPECT_EQ(FluidSystem(c, fluid).decayRates()[0], 0.0);
    const MhdSystem mhd(c, {spectrumWithHarmonic(-1e-11), 0.01, 0.02});
    EXPECT_EQ(mhd.decayRates()[0], 0.0);
    EXPECT_EQ(mhd.decayRates()[4], 0.0);

    for (const auto& build : {std::function<void()>([&] {
                                  FluidSystem(c, {spectrumWithHarmonic(-1e-3), 0.01});
                              }),
                              std::function<void()>([&] {
                                  MhdSystem(c, {spectrumWithHarmonic(-1e-3), 0.01});
                              })}) {
        try {
            build();
            ADD_FAILURE() << "kappa^2 = -1e-3 was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("kappa^2 of mode 1 is -0.001"), std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace modeflow
