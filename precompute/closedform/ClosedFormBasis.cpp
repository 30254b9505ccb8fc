#include "precompute/closedform/ClosedFormBasis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

#include "engine/core/Error.h"

namespace modeflow {

namespace {

/// One factor of one axis: wave number, phase and σ².
struct AxisWave {
    int wave = 0;
    int shift = 0;
    double sigma2 = 0.0;
};

using AxisWaves = std::array<std::vector<AxisWave>, 3>;

bool nyquist(const GridSpec& g, int a, int l) {
    return g.isPeriodic(a) && 2 * l == g.resolution[a];
}

/// The factors an axis carries, σ² ascending: on a wall l = 0..n−1 (scalars with a Dirichlet
/// wall: l = 1..n, phase 1, i.e. sines at the cell centres); on a periodic axis l = 0..⌊n/2⌋ in
/// phases 0 and 1, except those that vanish on the grid (`keep` decides for l = 0).
std::vector<AxisWave> axisWaves(const GridSpec& g, int a, bool dirichletWall,
                                bool keepZeroShifted) {
    std::vector<AxisWave> out;
    const int n = g.resolution[a];
    if (!g.isPeriodic(a)) {
        for (int l = dirichletWall ? 1 : 0; l < n + (dirichletWall ? 1 : 0); ++l)
            out.push_back({l, dirichletWall ? 1 : 0, 0.0});
    } else {
        for (int l = 0; 2 * l <= n; ++l)
            for (int shift = 0; shift < 2; ++shift) {
                if (shift == 0 && nyquist(g, a, l)) continue;  // sin(πx), cos(π(i+½)) vanish
                if (shift == 1 && l == 0 && !keepZeroShifted) continue;
                out.push_back({l, shift, 0.0});
            }
    }
    for (AxisWave& w : out) w.sigma2 = std::pow(axisSigma(g, a, w.wave), 2);
    return out;
}

/// Calls visit(choice) for every combination of one factor per used axis with Σσ² ≤ limit
/// (the lists ascend in σ², so each loop stops at the first factor over the limit).
template <typename Visit>
void forEachBelow(const AxisWaves& axes, int dim, double limit, Visit&& visit) {
    std::array<const AxisWave*, 3> choice{};
    static const AxisWave kUnused{};
    auto recurse = [&](auto&& self, int a, double sum) -> void {
        if (a == 3) {
            visit(choice);
            return;
        }
        if (a >= dim) {
            choice[std::size_t(a)] = &kUnused;
            self(self, a + 1, sum);
            return;
        }
        for (const AxisWave& w : axes[std::size_t(a)]) {
            if (sum + w.sigma2 > limit) break;
            choice[std::size_t(a)] = &w;
            self(self, a + 1, sum + w.sigma2);
        }
    };
    recurse(recurse, 0, 0.0);
}

double largestSigma2(const AxisWaves& axes, int dim) {
    double s = 0.0;
    for (int a = 0; a < dim; ++a) s += axes[std::size_t(a)].back().sigma2;
    return s;
}

/// Σ_x f² over the grid positions of one axis factor (whole positions for a sine, half ones for
/// a cosine): n/2, or n where the factor is constant in magnitude (l = 0, periodic l = n/2, the
/// Dirichlet wall's l = n).
double factorNorm(const GridSpec& g, int a, const AxisWave& w) {
    if (a >= g.dim) return 1.0;
    const int n = g.resolution[a];
    const bool flat = w.wave == 0 || nyquist(g, a, w.wave) || (!g.isPeriodic(a) && w.wave == n);
    return flat ? n : 0.5 * n;
}

struct Candidate {
    double kappa2;
    SeparableMode mode;
    int polarization;
};

bool before(const Candidate& x, const Candidate& y) {
    return std::tie(x.kappa2, x.mode.wave, x.mode.shift, x.polarization) <
           std::tie(y.kappa2, y.mode.wave, y.mode.shift, y.polarization);
}

/// The div-free fields of one choice of factors (see the header), normalized.
void velocityFields(const GridSpec& g, const std::array<const AxisWave*, 3>& c,
                    std::vector<Candidate>& out) {
    const int dim = g.dim;
    // s_a ≡ 0 on the faces: a wall's l = 0, a periodic phase-0 l = 0.
    auto sineVanishes = [&](int a) { return c[a]->wave == 0 && c[a]->shift == 0; };
    // f_a ≡ 0 at the cell centres: a periodic phase-1 l = 0.
    auto cosineVanishes = [&](int a) { return a < dim && c[a]->wave == 0 && c[a]->shift == 1; };
    std::vector<int> active;
    bool vacuous = false;
    for (int a = 0; a < dim; ++a) {
        vacuous = vacuous || cosineVanishes(a);
        bool on = !sineVanishes(a);
        for (int b = 0; b < dim; ++b) on = on && (b == a || !cosineVanishes(b));
        if (on) active.push_back(a);
    }
    std::array<double, 3> sigma{0.0, 0.0, 0.0};
    double kappa2 = 0.0;
    for (int a = 0; a < dim; ++a) {
        sigma[a] = axisSigma(g, a, c[a]->wave);
        kappa2 += c[a]->sigma2;
    }
    std::vector<std::array<double, 3>> amplitudes;
    if (vacuous) {
        // One component, divergence-free by itself (its f_a factor kills every other term).
        for (int a : active) {
            std::array<double, 3> e{0.0, 0.0, 0.0};
            e[a] = 1.0;
            amplitudes.push_back(e);
        }
    } else if (active.size() == 2) {
        std::array<double, 3> e{0.0, 0.0, 0.0};
        e[active[0]] = sigma[active[1]];
        e[active[1]] = -sigma[active[0]];
        amplitudes.push_back(e);
    } else if (active.size() == 3) {
        // (σ_y, −σ_x, 0) and σ × it: both ⟂ σ, orthogonal to each other.
        const std::array<double, 3> first{sigma[1], -sigma[0], 0.0};
        const std::array<double, 3> second{sigma[1] * first[2] - sigma[2] * first[1],
                                           sigma[2] * first[0] - sigma[0] * first[2],
                                           sigma[0] * first[1] - sigma[1] * first[0]};
        amplitudes = {first, second};
    }
    for (std::size_t p = 0; p < amplitudes.size(); ++p) {
        std::array<double, 3>& amp = amplitudes[p];
        // ⋆-norm²: |cell| Σ_a amp_a² ‖s_a‖² Π_{b≠a} ‖f_b‖² (per-axis sums of squares).
        double norm2 = 0.0;
        for (int a = 0; a < dim; ++a) {
            double term = amp[a] * amp[a] * factorNorm(g, a, *c[a]);
            for (int b = 0; b < dim; ++b)
                if (b != a) term *= factorNorm(g, b, *c[b]);
            norm2 += term;
        }
        double volume = 1.0;
        for (int a = 0; a < dim; ++a) volume *= g.spacing(a);
        const double scale = 1.0 / std::sqrt(volume * norm2);
        Candidate cand{kappa2, {}, int(p)};
        for (int a = 0; a < dim; ++a) {
            cand.mode.wave[a] = c[a]->wave;
            cand.mode.shift[a] = std::uint8_t(c[a]->shift);
            cand.mode.amplitude[a] = amp[a] * scale;
        }
        out.push_back(cand);
    }
}

/// The lowest `count` candidates of `fields` (a visitor adding the candidates of one choice of
/// factors), all of them sorted; grows the κ² limit until enough are found.
template <typename Fields>
std::vector<Candidate> lowest(const GridSpec& g, const AxisWaves& axes, std::int64_t count,
                              Fields&& fields) {
    double limit = 0.0;
    for (int a = 0; a < g.dim; ++a) {
        for (const AxisWave& w : axes[std::size_t(a)])
            if (w.sigma2 > 0.0) {
                limit = std::max(limit, w.sigma2);
                break;
            }
    }
    const double all = largestSigma2(axes, g.dim);
    for (;;) {
        std::vector<Candidate> found;
        forEachBelow(axes, g.dim, limit, [&](const auto& choice) { fields(choice, found); });
        if (std::int64_t(found.size()) >= count || limit >= all) {
            std::sort(found.begin(), found.end(), before);
            return found;
        }
        limit = std::min(2.0 * limit, all);
    }
}

AxisWaves velocityAxes(const GridSpec& g) {
    AxisWaves axes;
    for (int a = 0; a < g.dim; ++a) axes[std::size_t(a)] = axisWaves(g, a, false, true);
    return axes;
}

std::string plural(std::int64_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

std::int64_t closedFormDivergenceFreeDimension(const GridSpec& grid) {
    // faces − cells + 1 (one connected component); a periodic axis adds its plane of faces and
    // its uniform flow.
    std::int64_t cells = 1, faces = 0;
    for (int a = 0; a < grid.dim; ++a) cells *= grid.resolution[a];
    for (int a = 0; a < grid.dim; ++a)
        faces += cells / grid.resolution[a] * (grid.resolution[a] - (grid.isPeriodic(a) ? 0 : 1));
    return faces - cells + 1;
}

ClosedFormVelocity closedFormVelocityBasis(const GridSpec& grid,
                                           const std::vector<ModeRange>& ranges) {
    int highest = 0;
    for (const ModeRange& r : ranges) highest = std::max(highest, r.last);
    const std::int64_t available = closedFormDivergenceFreeDimension(grid);
    if (highest > available)
        throw Error("[basis]: asked for divergence-free mode " + std::to_string(highest) +
                    " but the domain holds only " + plural(available, "divergence-free field") +
                    " at this resolution");
    const std::vector<Candidate> sorted = lowest(
        grid, velocityAxes(grid), highest, [&](const auto& choice, std::vector<Candidate>& out) {
            velocityFields(grid, choice, out);
        });
    ClosedFormVelocity r;
    std::vector<double> values;
    for (const ModeRange& range : ranges)
        for (int m = range.first; m <= range.last; ++m) {
            const Candidate& c = sorted[std::size_t(m - 1)];
            values.push_back(c.kappa2);
            r.modes.push_back(c.mode);
            r.modeNumbers.push_back(m);
            r.harmonicCount += c.kappa2 == 0.0;
        }
    r.eigenvalues = Eigen::Map<Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
    return r;
}

ClosedFormScalar closedFormScalarBasis(const GridSpec& grid, int count, ScalarBoundary boundary) {
    const bool dirichlet = boundary == ScalarBoundary::Dirichlet;
    AxisWaves axes;
    std::int64_t cells = 1;
    for (int a = 0; a < grid.dim; ++a) {
        axes[std::size_t(a)] = axisWaves(grid, a, dirichlet, false);
        cells *= grid.resolution[a];
    }
    // Neumann leaves out the constant. Dirichlet keeps whatever the grid has: none with a wall,
    // the constant (μ² = 0) on a torus, which has no wall to be zero on.
    const int constants = dirichlet ? 0 : 1;
    if (count > cells - constants)
        throw Error("[basis].scalar_modes = " + std::to_string(count) + ": the domain holds only " +
                    plural(cells - constants, dirichlet ? "Dirichlet scalar mode"
                                                        : "non-constant Neumann scalar mode"));
    double volume = 1.0;
    for (int a = 0; a < grid.dim; ++a) volume *= grid.spacing(a);
    const std::vector<Candidate> sorted =
        lowest(grid, axes, count + constants, [&](const auto& c, std::vector<Candidate>& out) {
            Candidate cand{0.0, {}, 0};
            double norm2 = volume;
            for (int a = 0; a < grid.dim; ++a) {
                cand.kappa2 += c[a]->sigma2;
                cand.mode.wave[a] = c[a]->wave;
                cand.mode.shift[a] = std::uint8_t(c[a]->shift);
                norm2 *= factorNorm(grid, a, *c[a]);
            }
            cand.mode.amplitude[0] = 1.0 / std::sqrt(norm2);
            out.push_back(cand);
        });
    ClosedFormScalar r;
    r.omittedConstants = constants;
    r.eigenvalues.resize(count);
    for (int m = 0; m < count; ++m) {
        const Candidate& c = sorted[std::size_t(m + constants)];
        r.eigenvalues[m] = c.kappa2;
        r.modes.push_back(c.mode);
    }
    return r;
}

}  // namespace modeflow
