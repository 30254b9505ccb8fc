#include "engine/core/KappaSquared.h"

#include <cmath>
#include <limits>

#include "engine/core/Error.h"
#include "engine/core/NumberText.h"

namespace modeflow {

double firstNonZeroKappaSquared(const Eigen::VectorXd& kappaSquared, double anchor) {
    double first = std::numeric_limits<double>::infinity();
    for (const double k2 : kappaSquared)
        if (k2 > kHarmonicTolerance * anchor && k2 < first) first = k2;
    return std::isfinite(first) ? first : anchor;
}

Eigen::VectorXd checkedKappaSquared(const Eigen::VectorXd& kappaSquared, double firstNonZero,
                                    const std::string& consumer) {
    const double tolerance = kHarmonicTolerance * firstNonZero;
    Eigen::VectorXd checked = kappaSquared;
    for (Eigen::Index i = 0; i < checked.size(); ++i) {
        const double k2 = checked[i];
        const std::string mode = consumer + ": kappa^2 of mode " + std::to_string(i + 1) + " is ";
        if (!std::isfinite(k2)) throw Error(mode + numberText(k2) + "; the basis cache is damaged");
        if (k2 < -tolerance)
            throw Error(mode + numberText(k2) + ", negative beyond round-off (the tolerance is " +
                        numberText(kHarmonicTolerance) + " of the first non-zero kappa^2, " +
                        numberText(firstNonZero) + "); the basis cache is damaged");
        if (std::abs(k2) <= tolerance) checked[i] = 0.0;
    }
    return checked;
}

Eigen::VectorXd checkedKappaSquared(const Eigen::VectorXd& kappaSquared,
                                    const std::string& consumer) {
    const double largest = kappaSquared.size() == 0 ? 0.0 : kappaSquared.cwiseAbs().maxCoeff();
    return checkedKappaSquared(kappaSquared, firstNonZeroKappaSquared(kappaSquared, largest),
                               consumer);
}

}  // namespace modeflow
