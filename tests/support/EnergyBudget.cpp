#include "tests/support/EnergyBudget.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace modeflow::testing {

Eigen::VectorXd unitEnergyState(int n, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    Eigen::VectorXd v(n);
    for (int k = 0; k < n; ++k) v[k] = normal(random);
    return v * std::sqrt(2.0 / v.squaredNorm());
}

EnergyBudget midpointEnergyBudget(
    ModalIntegrator& integrator, const LinearModalTerm& term, Eigen::VectorXd& v, double h,
    int steps,
    const std::function<void(const Eigen::VectorXd&, const Eigen::VectorXd&)>& eachStep) {
    const double e0 = 0.5 * v.squaredNorm();
    EnergyBudget budget;
    double sum = 0.0;
    for (int step = 0; step < steps; ++step) {
        const Eigen::VectorXd before = v;
        integrator.step(v, h);
        const Eigen::VectorXd mid = 0.5 * (before + v);
        Eigen::VectorXd dMid;
        term.apply(mid, dMid);
        const double gap = 0.5 * (v.squaredNorm() - before.squaredNorm()) - h * mid.dot(dMid);
        budget.worstStep = std::max(budget.worstStep, std::abs(gap) / e0);
        sum += gap;
        if (eachStep) eachStep(mid, dMid);
    }
    budget.drift = std::abs(sum) / e0;
    return budget;
}

}  // namespace modeflow::testing
