/// @file CombustionTest.cpp
/// The fire's rule (engine/simulation/Combustion.h): fuel hotter than the ignition burns first
/// order, exactly, conserving fuel into flame, heat and smoke.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/simulation/Combustion.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/ThrownMessage.h"

namespace modeflow {
namespace {

/// Four cells: cold, at the ignition, hot, hot but outside the fluid.
SmokeFields fourCells() {
    SmokeFields f;
    f.density = {0.1, 0.2, 0.3, 0.4};
    f.temperature = {0.5, 1.0, 1.5, 2.0};
    f.fuel = {1.0, 1.0, 2.0, 1.0};
    f.flame = {9.0, 9.0, 9.0, 9.0};  // the last step's: replaced
    return f;
}

const std::vector<std::uint8_t> kMask{1, 1, 1, 0};

TEST(Combustion, OnlyFuelHotterThanTheIgnitionBurnsAtTheExactFirstOrderRate) {
    const FireSpec fire = testing::testFire();
    SmokeFields f = fourCells();
    const double dt = 0.1;
    burn(fire, kMask, dt, f);
    const double burned = 2.0 * (1.0 - std::exp(-3.0 * dt));
    EXPECT_EQ(f.fuel[0], 1.0);  // cold
    EXPECT_EQ(f.fuel[1], 1.0);  // at the ignition: not above it
    EXPECT_NEAR(f.fuel[2], 2.0 - burned, 1e-15);
    EXPECT_EQ(f.fuel[3], 1.0);  // outside the fluid
    EXPECT_EQ(f.flame[0], 0.0);
    EXPECT_EQ(f.flame[3], 0.0);
    EXPECT_NEAR(f.flame[2], burned / dt, 1e-13);
    EXPECT_NEAR(f.temperature[2], 1.5 + 2.0 * burned, 1e-15);
    EXPECT_NEAR(f.density[2], 0.3 + 0.25 * burned, 1e-15);
    EXPECT_EQ(f.temperature[0], 0.5);
    EXPECT_EQ(f.density[1], 0.2);
}

TEST(Combustion, FuelIsConservedIntoFlameAndTwoHalfStepsMakeOneStep) {
    const FireSpec fire = testing::testFire();
    SmokeFields whole = fourCells(), halves = fourCells();
    burn(fire, kMask, 0.2, whole);
    double flameTimesDt = 0.0;
    for (int half = 0; half < 2; ++half) {
        burn(fire, kMask, 0.1, halves);
        flameTimesDt += halves.flame[2] * 0.1;
    }
    EXPECT_NEAR(whole.fuel[2], halves.fuel[2], 1e-15);  // e^{-r dt} = (e^{-r dt/2})²
    EXPECT_NEAR(2.0 - halves.fuel[2], flameTimesDt, 1e-15);
    EXPECT_NEAR(whole.temperature[2], halves.temperature[2], 1e-14);
    // A step as long as any: the fuel never goes below 0.
    SmokeFields huge = fourCells();
    burn(fire, kMask, 1e6, huge);
    EXPECT_GE(huge.fuel[2], 0.0);
    EXPECT_NEAR(huge.temperature[2], 1.5 + 2.0 * 2.0, 1e-12);
}

TEST(Combustion, BadFieldsAndStepsAreRefused) {
    const FireSpec fire = testing::testFire();
    SmokeFields f = fourCells();
    f.flame.clear();
    EXPECT_NE(testing::thrownMessage([&] { burn(fire, kMask, 0.1, f); }).find("fuel and flame"),
              std::string::npos);
    SmokeFields g = fourCells();
    for (const double dt : {0.0, -1.0, std::nan("")})
        EXPECT_NE(testing::thrownMessage([&] { burn(fire, kMask, dt, g); }).find("not positive"),
                  std::string::npos)
            << dt;
}

}  // namespace
}  // namespace modeflow
