#include "engine/dynamics/InitialConditions.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/NumberText.h"
#include "engine/dynamics/ModalDivergence.h"

namespace modeflow {
namespace {

/// Uniform in (0, 1]: 53 random bits, never 0 so that the logarithm below is finite.
double uniform(std::mt19937_64& rng) {
    return double((rng() >> 11) + 1) * 0x1p-53;
}

double standardNormal(std::mt19937_64& rng) {
    const double radius = std::sqrt(-2.0 * std::log(uniform(rng)));
    return radius * std::cos(2.0 * std::numbers::pi * uniform(rng));
}

}  // namespace

Eigen::VectorXd randomVelocity(int modeCount, const RandomVelocitySpec& spec) {
    const int last = spec.lastMode < 0 ? modeCount - 1 : spec.lastMode;
    if (spec.firstMode < 0 || spec.firstMode > last || last >= modeCount) {
        throw Error("random velocity: the mode band [" + std::to_string(spec.firstMode) + ", " +
                    std::to_string(last) + "] is not inside the basis of " +
                    std::to_string(modeCount) + " modes");
    }
    if (!(spec.energy >= 0.0) || !std::isfinite(spec.energy)) {
        throw Error("random velocity: the energy must be finite and non-negative");
    }
    std::mt19937_64 rng(spec.seed);
    Eigen::VectorXd v = Eigen::VectorXd::Zero(modeCount);
    for (int i = spec.firstMode; i <= last; ++i) v[i] = standardNormal(rng);
    v *= std::sqrt(2.0 * spec.energy) / v.norm();
    requireRepresentableState(v, "random velocity");
    return v;
}

Eigen::VectorXd modalAmplitudes(int modeCount,
                                const std::vector<std::pair<int, double>>& amplitudes) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(modeCount);
    std::vector<bool> given(std::size_t(std::max(modeCount, 0)), false);
    for (const auto& [index, amplitude] : amplitudes) {
        if (index < 0 || index >= modeCount) {
            throw Error("modal amplitudes: mode " + std::to_string(index) +
                        " is outside the basis of " + std::to_string(modeCount) + " modes");
        }
        if (given[std::size_t(index)]) {
            throw Error("modal amplitudes: mode " + std::to_string(index) + " is given twice");
        }
        given[std::size_t(index)] = true;
        v[index] = amplitude;
    }
    requireRepresentableState(v, "modal amplitudes");
    return v;
}

void requireRepresentableState(const Eigen::VectorXd& state, const std::string& what) {
    for (Eigen::Index i = 0; i < state.size(); ++i)
        if (!std::isfinite(state[i]))
            throw Error(what + ": the modal state is not finite (mode " + std::to_string(i + 1) +
                        " is " + numberText(state[i]) + ")");
    // stableNorm() itself does not overflow before |v| does.
    const double largest = largestSteppableNorm();
    const double norm = state.stableNorm();
    if (norm > largest)
        throw Error(what + ": the modal state is too large for double precision: |v| = " +
                    numberText(norm) + ", and a step takes |v|^4 (keep |v| below " +
                    numberText(largest, 2) + ")");
}

}  // namespace modeflow
