/// @file InitialConditionsTest.cpp
/// Random band-limited and explicit modal initial velocities.

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/InitialConditions.h"

namespace modeflow {
namespace {

TEST(RandomVelocity, HasTheEnergyAndTheBand) {
    const Eigen::VectorXd v = randomVelocity(40, {5, 19, 2.5, 7});
    EXPECT_NEAR(energy(v), 2.5, 1e-14);
    for (int i = 0; i < 40; ++i) {
        if (i < 5 || i > 19) {
            EXPECT_EQ(v[i], 0.0) << "mode " << i << " is outside the band";
        } else {
            EXPECT_NE(v[i], 0.0) << "mode " << i << " is inside the band";
        }
    }
}

TEST(RandomVelocity, IsReproducibleAndSeedDependent) {
    const RandomVelocitySpec spec{0, -1, 1.0, 42};
    EXPECT_EQ(randomVelocity(30, spec), randomVelocity(30, spec));
    RandomVelocitySpec other = spec;
    other.seed = 43;
    EXPECT_GT((randomVelocity(30, spec) - randomVelocity(30, other)).norm(), 0.1);
    // Standard-normal amplitudes: over many modes the sample kurtosis is near 3.
    const Eigen::VectorXd many = randomVelocity(20000, spec);
    const double m2 = many.array().square().mean(), m4 = many.array().pow(4).mean();
    EXPECT_NEAR(m4 / (m2 * m2), 3.0, 0.2);
}

TEST(RandomVelocity, RejectsBadBands) {
    EXPECT_THROW(randomVelocity(10, {5, 10, 1.0, 1}), Error);
    EXPECT_THROW(randomVelocity(10, {6, 5, 1.0, 1}), Error);
    EXPECT_THROW(randomVelocity(10, {-1, 5, 1.0, 1}), Error);
    EXPECT_THROW(randomVelocity(10, {0, 5, -1.0, 1}), Error);
}

TEST(ModalAmplitudes, SetsTheGivenModes) {
    const Eigen::VectorXd v = modalAmplitudes(6, {{0, 1.5}, {4, -2.0}});
    Eigen::VectorXd expected(6);
    expected << 1.5, 0, 0, 0, -2.0, 0;
    EXPECT_EQ(v, expected);
    EXPECT_THROW(modalAmplitudes(6, {{6, 1.0}}), Error);
    EXPECT_THROW(modalAmplitudes(6, {{2, 1.0}, {2, 3.0}}), Error);
}

/// The message of the Error `build` throws, or "" when it throws none.
template <typename Build>
std::string refusal(Build build) {
    try {
        build();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(InitialStates, StatesTooLargeForAStepAreRefused) {
    // ½|v|² = 1e300 is finite, its square (every step takes norms of C·v·v) is not; 1e308
    // makes the state itself infinite.
    for (const auto& c : {std::pair{1e300, "too large"}, std::pair{1e308, "not finite"}}) {
        const double huge = c.first;  // not a structured binding: clang 14 cannot capture one
        const char* why = c.second;
        const std::string message = refusal([&] { randomVelocity(8, {0, -1, huge, 1}); });
        EXPECT_EQ(message.rfind("random velocity: ", 0), 0u) << huge << ": " << message;
        EXPECT_NE(message.find(why), std::string::npos) << huge << ": " << message;
    }
    const std::string amplitudes = refusal([] { modalAmplitudes(4, {{1, 1e200}}); });
    EXPECT_EQ(amplitudes.rfind("modal amplitudes: ", 0), 0u) << amplitudes;
    EXPECT_NE(amplitudes.find("|v| = 1e+200"), std::string::npos) << amplitudes;
    // Large but squarable states stay.
    EXPECT_NEAR(energy(randomVelocity(8, {0, -1, 1e100, 1})) / 1e100, 1.0, 1e-12);
    EXPECT_EQ(modalAmplitudes(4, {{1, 1e70}})[1], 1e70);
}

TEST(InitialStates, NonFiniteStatesAreRefusedNamingTheMode) {
    Eigen::VectorXd v = Eigen::VectorXd::Ones(5);
    v[3] = NAN;
    const std::string message = refusal([&] { requireRepresentableState(v, "test"); });
    EXPECT_NE(message.find("test: the modal state is not finite (mode 4 is nan)"),
              std::string::npos)
        << message;
}

}  // namespace
}  // namespace modeflow
