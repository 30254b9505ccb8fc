#include "tools/validate/Fit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"

namespace modeflow::validate {

double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2)
        throw Error("order fit: needs two or more points, one y per x");
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]), my += std::log(y[i]);
    mx /= double(x.size()), my /= double(y.size());
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double dx = std::log(x[i]) - mx;
        sxy += dx * (std::log(y[i]) - my);
        sxx += dx * dx;
    }
    return sxy / sxx;
}

double maxRelativeError(const std::vector<double>& computed, const std::vector<double>& exact) {
    if (computed.size() < exact.size())
        throw Error("eigenvalue error: " + std::to_string(computed.size()) +
                    " computed values for " + std::to_string(exact.size()) + " exact ones");
    double worst = 0.0;
    for (std::size_t i = 0; i < exact.size(); ++i)
        worst = std::max(worst, std::abs(computed[i] - exact[i]) / exact[i]);
    return worst;
}

}  // namespace modeflow::validate
