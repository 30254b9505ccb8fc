#include "tools/validate/ExactSpectra.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "engine/core/Error.h"

namespace modeflow::validate {
namespace {

/// Roots of f on (0, limit), by a scan with step 0.01 and bisection to round-off.
std::vector<double> roots(const std::function<double(double)>& f, double limit) {
    std::vector<double> found;
    const double step = 0.01;
    double a = step, fa = f(a);
    for (double b = a + step; b < limit; b += step) {
        const double fb = f(b);
        if (fa == 0.0) found.push_back(a);
        if (fa * fb < 0.0) {
            double lo = a, hi = b, flo = fa;
            for (int i = 0; i < 100 && hi - lo > 1e-15 * hi; ++i) {
                const double mid = 0.5 * (lo + hi), fm = f(mid);
                if ((fm < 0.0) == (flo < 0.0))
                    lo = mid, flo = fm;
                else
                    hi = mid;
            }
            found.push_back(0.5 * (lo + hi));
        }
        a = b, fa = fb;
    }
    return found;
}

double besselDerivative(int m, double x) {
    return m == 0 ? -std::cyl_bessel_j(1, x)
                  : 0.5 * (std::cyl_bessel_j(m - 1, x) - std::cyl_bessel_j(m + 1, x));
}

double sphericalDerivative(int l, double x) {
    return l == 0 ? -std::sph_bessel(1, x)
                  : std::sph_bessel(l - 1, x) - (l + 1) / x * std::sph_bessel(l, x);
}

}  // namespace

std::vector<double> unitBallSpectrum(int dim, SpectrumKind kind, int count) {
    // Wide enough for the first few dozen eigenvalues of each kind.
    const double limit = 20.0;
    const int orders = 16;
    std::vector<double> values;
    for (int order = 0; order <= orders; ++order) {
        const int multiplicity = dim == 2 ? (order == 0 ? 1 : 2) : 2 * order + 1;
        std::vector<std::function<double(double)>> equations;
        if (dim == 2) {
            if (kind == SpectrumKind::Neumann)
                equations = {[order](double x) { return besselDerivative(order, x); }};
            else
                equations = {[order](double x) { return std::cyl_bessel_j(order, x); }};
        } else if (kind == SpectrumKind::Dirichlet) {
            equations = {[order](double x) { return std::sph_bessel(order, x); }};
        } else if (kind == SpectrumKind::Neumann) {
            equations = {[order](double x) { return sphericalDerivative(order, x); }};
        } else if (order >= 1) {
            equations = {[order](double x) { return std::sph_bessel(order, x); },
                         [order](double x) {
                             return std::sph_bessel(order, x) + x * sphericalDerivative(order, x);
                         }};
        }
        for (const auto& f : equations)
            for (const double root : roots(f, limit))
                values.insert(values.end(), std::size_t(multiplicity), root * root);
    }
    std::sort(values.begin(), values.end());
    if (int(values.size()) < count)
        throw Error("exact spectrum: " + std::to_string(count) + " eigenvalues asked for, " +
                    std::to_string(values.size()) + " known");
    values.resize(std::size_t(count));
    return values;
}

}  // namespace modeflow::validate
