/// @file ModalDivergenceTest.cpp
/// The check every simulator makes after each step: a modal state that is not finite, or too
/// large for the next step and the reconstruction to stay finite, stops the run as diverged.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "engine/dynamics/ModalDivergence.h"

namespace modeflow {
namespace {

TEST(ModalDivergence, ASteppableStatePasses) {
    EXPECT_NO_THROW(requireFiniteModalState(Eigen::VectorXd::Constant(40, 1e6), 3, 0.3));
    EXPECT_NO_THROW(requireFiniteModalState(Eigen::VectorXd::Zero(0), 1, 0.1));
}

TEST(ModalDivergence, ANonFiniteStateIsDivergedAtItsStep) {
    Eigen::VectorXd v = Eigen::VectorXd::Ones(8);
    v[5] = std::numeric_limits<double>::quiet_NaN();
    try {
        requireFiniteModalState(v, 7, 0.35);
        FAIL() << "a NaN state passed";
    } catch (const ModalStateDiverged& e) {
        EXPECT_EQ(e.step(), 7);
        EXPECT_STREQ(e.what(), "the modal state diverged at step 7 (t = 0.35)");
    }
}

TEST(ModalDivergence, AFiniteStateTooLargeToStepIsDivergedToo) {
    // Finite, but |v|⁴ overflows and so does the face velocity Ψv a frame reconstructs: an
    // unstable integrator passes through such states on its way to infinity.
    const Eigen::VectorXd v = Eigen::VectorXd::Constant(8, 1e200);
    ASSERT_TRUE(v.allFinite());
    EXPECT_THROW(requireFiniteModalState(v, 4, 0.2), ModalStateDiverged);
    const Eigen::VectorXd justBelow = Eigen::VectorXd::Constant(1, 0.99 * largestSteppableNorm());
    EXPECT_NO_THROW(requireFiniteModalState(justBelow, 4, 0.2));
    EXPECT_TRUE(std::isfinite(std::pow(0.99 * largestSteppableNorm(), 4.0)))
        << "largestSteppableNorm() = " << largestSteppableNorm();
}

TEST(ModalDivergence, TheAdviceSuggestsMidpointOnlyToTheExplicitRules) {
    const ModalStateDiverged diverged(1, 0.01);
    EXPECT_EQ(divergenceAdvice(diverged, "rk4", "--dt"),
              std::string(diverged.what()) +
                  "; rk4 is unstable at this step size: lower --dt or use midpoint");
    for (const char* implicit : {"midpoint", "trapezoidal"})
        EXPECT_EQ(divergenceAdvice(diverged, implicit, "[simulation].dt"),
                  std::string(diverged.what()) + "; " + implicit +
                      " is unstable at this step size: lower [simulation].dt");
}

}  // namespace
}  // namespace modeflow
