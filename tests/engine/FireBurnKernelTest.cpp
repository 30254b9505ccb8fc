/// @file FireBurnKernelTest.cpp
/// shaders/fire_burn.comp (FireBurnKernel) against the CPU reference's burn
/// (engine/simulation/Combustion.h) on the same float-rounded fields: a uniform block of fuel
/// held above the ignition burns at the analytic rate, step after step; no fuel burns at or
/// below the ignition; the flame is the fuel burned per unit time; the temperature read by the
/// buoyancy (the state's temperature alone) follows the heat released.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "engine/device/FireBurn.h"
#include "engine/device/SmokeState.h"
#include "engine/simulation/Combustion.h"
#include "engine/vulkan/CommandSequence.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/ThrownMessage.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using device::FireBurnKernel;
using device::SmokePair;
using device::SmokeState;

std::vector<float> toFloat(const std::vector<double>& v) {
    return std::vector<float>(v.begin(), v.end());
}

class FireBurnKernelTest : public testing::VulkanTest {};

TEST_P(FireBurnKernelTest, BurnsAsTheCpuReferenceAndAtTheAnalyticRate) {
    {
        const MacGrid basis = testing::smokeTestGrid(2, 16);
        const std::vector<std::uint8_t> mask = testing::ballMask(basis, 0.85);
        const std::size_t cells = mask.size();
        // Fuel everywhere; a hot block (held hot: the test writes its temperature back each
        // step) beside cold air and air exactly at the ignition.
        SmokeFields fields;
        fields.density.assign(cells, 0.1);
        fields.temperature.resize(cells);
        fields.fuel.assign(cells, 2.0);
        fields.flame.assign(cells, 7.0);  // the last step's: replaced everywhere
        for (std::size_t c = 0; c < cells; ++c) {
            fields.temperature[c] = c % 3 == 0 ? 1.5 : c % 3 == 1 ? 0.5 : 1.0;
            if (!mask[c]) fields.density[c] = fields.temperature[c] = fields.fuel[c] = 0.0;
            if (!mask[c]) fields.flame[c] = 0.0;
        }
        SmokeState state(context(), basis, 1, mask, true);
        const FireBurnKernel kernel(context());
        const FireSpec fire = testing::testFire();
        const double dt = 0.05;
        state.upload(toFloat(fields.density), toFloat(fields.temperature));
        state.upload(toFloat(fields.fuel), toFloat(fields.flame), SmokePair::Fuel);
        vulkan::CommandSequence sequence(context());
        kernel.record(sequence, state, fire, dt);
        sequence.submitAndWait();
        burn(fire, mask, dt, fields);

        std::vector<float> density(cells), temperature(cells), fuel(cells), flame(cells),
            temperatureAlone(cells), flameAlone(cells);
        state.download(density, temperature);
        state.download(fuel, flame, SmokePair::Fuel);
        state.temperature().download<float>(temperatureAlone);
        state.second(SmokePair::Fuel).download<float>(flameAlone);
        int hot = 0;
        for (std::size_t c = 0; c < cells; ++c) {
            EXPECT_NEAR(fuel[c], fields.fuel[c], 1e-6) << c;
            EXPECT_NEAR(flame[c], fields.flame[c], 1e-5) << c;
            EXPECT_NEAR(temperature[c], fields.temperature[c], 1e-6) << c;
            EXPECT_NEAR(density[c], fields.density[c], 1e-6) << c;
            EXPECT_EQ(temperatureAlone[c], temperature[c]) << c;
            EXPECT_EQ(flameAlone[c], flame[c]) << c;
            if (mask[c] && c % 3 != 0) {
                EXPECT_EQ(fuel[c], 2.0f) << "cell " << c << " is not above the ignition";
                EXPECT_EQ(flame[c], 0.0f) << c;
            }
            hot += mask[c] && c % 3 == 0;
        }
        ASSERT_GT(hot, 20);

        // Held above the ignition, the fuel decays as F0 e^{-r t}, its flame r F e^{...}:
        // ten more steps recorded into one submission.
        for (int step = 0; step < 10; ++step) kernel.record(sequence, state, fire, dt);
        sequence.submitAndWait();
        state.download(fuel, flame, SmokePair::Fuel);
        const double left = 2.0 * std::exp(-fire.burnRate * 11 * dt);
        const double lastBurned =
            2.0 * std::exp(-fire.burnRate * 10 * dt) * -std::expm1(-fire.burnRate * dt);
        for (std::size_t c = 0; c < cells; c += 3)
            if (mask[c]) {
                EXPECT_NEAR(fuel[c], left, 1e-5 * 2.0) << c;
                EXPECT_NEAR(flame[c], lastBurned / dt, 1e-4) << c;
            }
    }
    expectNoValidationMessages();
}

TEST_P(FireBurnKernelTest, AStateWithoutFuelOrABadStepIsRefused) {
    {
        const MacGrid basis = testing::smokeTestGrid(2, 8);
        const std::vector<std::uint8_t> mask = testing::wholeMask(basis);
        SmokeState smokeOnly(context(), basis, 1, mask), burning(context(), basis, 1, mask, true);
        const FireBurnKernel kernel(context());
        vulkan::CommandSequence sequence(context());
        EXPECT_NE(testing::thrownMessage([&] {
                      kernel.record(sequence, smokeOnly, testing::testFire(), 0.1);
                  }).find("carries no fuel"),
                  std::string::npos);
        for (const double dt : {0.0, -1.0, std::nan("")})
            EXPECT_NE(testing::thrownMessage([&] {
                          kernel.record(sequence, burning, testing::testFire(), dt);
                      }).find("not positive and finite"),
                      std::string::npos)
                << dt;
        std::vector<float> values(mask.size());
        EXPECT_NE(testing::thrownMessage([&] {
                      smokeOnly.upload(values, values, SmokePair::Fuel);
                  }).find("without fire"),
                  std::string::npos);
    }
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(PlainAndValidated, FireBurnKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
