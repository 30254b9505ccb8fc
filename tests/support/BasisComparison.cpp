#include "tests/support/BasisComparison.h"

#include <algorithm>
#include <cmath>

namespace modeflow::testing {

double eigenvalueDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    double worst = 0.0;
    for (Eigen::Index i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) worst = std::max(worst, std::abs(a[i] - b[i]) / std::abs(b[i]));
    return worst;
}

double spanDifference(const Eigen::VectorXd& values, const Eigen::MatrixXd& a,
                      const Eigen::MatrixXd& b, const Eigen::VectorXd& mass) {
    double worst = 0.0;
    for (Eigen::Index first = 0; first < values.size();) {
        Eigen::Index end = first + 1;
        while (end < values.size() && values[end] - values[end - 1] <= 1e-3 * values[end]) ++end;
        const Eigen::MatrixXd ag = a.middleCols(first, end - first);
        const Eigen::MatrixXd bg = b.middleCols(first, end - first);
        const Eigen::MatrixXd rest = bg - ag * (ag.transpose() * mass.asDiagonal() * bg);
        worst = std::max(worst, rest.cwiseAbs().maxCoeff() / bg.cwiseAbs().maxCoeff());
        first = end;
    }
    return worst;
}

}  // namespace modeflow::testing
