// Structural coefficients from a basis (seed eq. 6.7): exact antisymmetry by construction,
// second-order convergence to the continuum integral, and the 2D steady-eigenmode property.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/core/PackedLayout.h"
#include "precompute/Precompute.h"
#include "precompute/coefficients/CoefficientAssembly.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// A free-slip box mode by its stream function ψ = sin(lπx/a) sin(mπy/b); u = (∂yψ, −∂xψ),
/// ω = ∂x u_y − ∂y u_x = −Δψ = κ²ψ.
struct BoxMode {
    int l, m;
    double a, b;
    double psi(double x, double y) const {
        return std::sin(l * M_PI * x / a) * std::sin(m * M_PI * y / b);
    }
    double kappa2() const { return std::pow(l * M_PI / a, 2) + std::pow(m * M_PI / b, 2); }
    double omega(double x, double y) const { return kappa2() * psi(x, y); }
    double ux(double x, double y) const {
        return m * M_PI / b * std::sin(l * M_PI * x / a) * std::cos(m * M_PI * y / b);
    }
    double uy(double x, double y) const {
        return -l * M_PI / a * std::cos(l * M_PI * x / a) * std::sin(m * M_PI * y / b);
    }
};

const std::vector<BoxMode> kModes = {{1, 1, 1.3, 1.0}, {2, 1, 1.3, 1.0}, {1, 2, 1.3, 1.0},
                                     {2, 2, 1.3, 1.0}, {3, 1, 1.3, 1.0}, {1, 3, 1.3, 1.0}};

/// A field on a periodic box [0, a] × [0, b] by its stream function
/// ψ = A sin(2πl x/a + p) sin(2πm y/b + q) + U y − V x: the linear part is the uniform flow (U, V),
/// a harmonic field (ω = 0); u = (∂yψ, −∂xψ), ω = −Δψ.
struct TorusMode {
    double A;
    int l, m;
    double p, q, U, V;
    double a = 1.3, b = 1.0;
    double kx() const { return 2.0 * M_PI * l / a; }
    double ky() const { return 2.0 * M_PI * m / b; }
    double psi(double x, double y) const {
        return A * std::sin(kx() * x + p) * std::sin(ky() * y + q) + U * y - V * x;
    }
    double omega(double x, double y) const {
        return A * (kx() * kx() + ky() * ky()) * std::sin(kx() * x + p) * std::sin(ky() * y + q);
    }
    double ux(double x, double y) const {
        return A * ky() * std::sin(kx() * x + p) * std::cos(ky() * y + q) + U;
    }
    double uy(double x, double y) const {
        return -A * kx() * std::cos(kx() * x + p) * std::sin(ky() * y + q) + V;
    }
};

const std::vector<TorusMode> kTorusModes = {
    {0.0, 0, 0, 0.0, 0.0, 1.0, 0.0}, {0.0, 0, 0, 0.0, 0.0, 0.0, 1.0},
    {1.0, 1, 1, 0.0, 0.0, 0.0, 0.0}, {1.0, 1, 2, 0.5, 0.0, 0.0, 0.0},
    {1.0, 2, 1, 0.0, 0.7, 0.0, 0.0}, {1.0, 1, 1, 1.1, 0.3, 0.0, 0.0}};

/// ∫ ω_i (u_k × u_j) over the box by tensor Gauss–Legendre quadrature (exact to round-off for
/// these trigonometric products at this order).
template <typename Mode>
double continuumCoefficient(const Mode& k, const Mode& i, const Mode& j) {
    static const double node[] = {-0.9739065285171717, -0.8650633666889845, -0.6794095682990244,
                                  -0.4333953941292472, -0.1488743389816312, 0.1488743389816312,
                                  0.4333953941292472,  0.6794095682990244,  0.8650633666889845,
                                  0.9739065285171717};
    static const double weight[] = {0.0666713443086881, 0.1494513491505806, 0.2190863625159820,
                                    0.2692667193099963, 0.2955242247147529, 0.2955242247147529,
                                    0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                    0.0666713443086881};
    const int panels = 8;
    double sum = 0.0;
    for (int px = 0; px < panels; ++px)
        for (int py = 0; py < panels; ++py)
            for (int qx = 0; qx < 10; ++qx)
                for (int qy = 0; qy < 10; ++qy) {
                    const double x = k.a * (px + 0.5 * (node[qx] + 1.0)) / panels;
                    const double y = k.b * (py + 0.5 * (node[qy] + 1.0)) / panels;
                    const double w = weight[qx] * weight[qy] * 0.25 * k.a * k.b / (panels * panels);
                    const double omega = i.omega(x, y);
                    sum += w * omega * (k.ux(x, y) * j.uy(x, y) - k.uy(x, y) * j.ux(x, y));
                }
    return sum;
}

/// Discrete coefficients of the modes sampled as exact face fluxes (ψ differences) on a grid of
/// [0, 1.3] × [0, 1] with `resolution` cells along y.
template <typename Mode>
std::vector<double> discreteCoefficients(int resolution, const std::vector<Mode>& fields,
                                         bool periodic) {
    SceneSpec scene = testing::gridScene({int(std::lround(1.3 * resolution)), resolution, 1},
                                         {0.0, 0.0, 0.0}, {1.3, 1.0, 0.0}, 2);
    scene.grid.periodic = {periodic, periodic, false};
    const CubicalComplex cx(scene.grid);
    const Domain domain({}, 2, 1.0);
    const CutCellMeasures measures = measureCutCells(cx, domain, BoundaryTreatment::CutCell, 1);
    const CutCellDec dec = buildCutCellDec(cx, measures, WallKind::FreeSlip);
    Eigen::MatrixXd modes(dec.faces.size(), Eigen::Index(fields.size()));
    const double hx = scene.grid.spacing(0), hy = scene.grid.spacing(1);
    for (std::int64_t f = 0; f < dec.faces.size(); ++f) {
        const Element e = cx.element(1, dec.faces.toGlobal[f]);
        const double x0 = e.pos[0] * hx, y0 = e.pos[1] * hy;
        const bool xNormal = e.axes == 2u;  // extends along y
        for (size_t m = 0; m < fields.size(); ++m) {
            const Mode& b = fields[m];
            // Flux along +normal: ψ(end) − ψ(start) for x-normal faces, the opposite for y-normal.
            modes(f, Eigen::Index(m)) =
                xNormal ? b.psi(x0, y0 + hy) - b.psi(x0, y0) : b.psi(x0, y0) - b.psi(x0 + hx, y0);
        }
    }
    return assembleStructuralCoefficients(cx, measures, dec, modes);
}

/// Max |C − C_exact| / max |C_exact| at 16, 32 and 64 cells across, each step at least 3.3 times
/// smaller (second order), below `finest` at 64.
template <typename Mode>
void expectQuadraticConvergence(const std::vector<Mode>& fields, bool periodic, double finest,
                                const char* label) {
    const size_t n = fields.size();
    std::vector<double> exact(packedSize(n));
    double scale = 0.0;
    for (size_t k = 0; k < n; ++k)
        for (size_t j = k + 1; j < n; ++j)
            for (size_t i = 0; i < n; ++i) {
                const double c = continuumCoefficient(fields[k], fields[i], fields[j]);
                exact[packedIndex(n, k, i, j)] = c;
                scale = std::max(scale, std::abs(c));
            }
    ASSERT_GT(scale, 1.0) << "the chosen modes must interact";
    double previous = 0.0;
    for (int res : {16, 32, 64}) {
        const std::vector<double> c = discreteCoefficients(res, fields, periodic);
        double err = 0.0;
        for (size_t p = 0; p < c.size(); ++p) err = std::max(err, std::abs(c[p] - exact[p]));
        err /= scale;
        std::printf("%s, %d cells across: max |C − C_exact| / max |C_exact| = %.3e", label, res,
                    err);
        if (previous > 0.0) std::printf("  (order %.2f)", std::log2(previous / err));
        std::printf("\n");
        if (previous > 0.0) {
            EXPECT_GT(previous / err, 3.3) << label << ": not second order at " << res;
        }
        previous = err;
    }
    EXPECT_LT(previous, finest) << label;
}

TEST(CoefficientAssembly, BoxCoefficientsConvergeQuadratically2D) {
    expectQuadraticConvergence(kModes, false, 5e-3, "box 2D");
}

TEST(CoefficientAssembly, TorusCoefficientsConvergeQuadratically2D) {
    // Periodic fields, the two uniform flows among them: the quadrature wraps across the seams.
    expectQuadraticConvergence(kTorusModes, true, 1e-2,
                               "torus 2D");  // twice the box's wave numbers
}

TEST(CoefficientAssembly, DiskEigenmodeSelfInteractionVanishesUnderRefinement) {
    // In 2D every Laplacian eigenmode is a steady Euler flow: u × ω is a gradient, so its
    // projection C[m][k][k] on every mode m tends to zero.
    double previous = 0.0;
    for (int res : {64, 128}) {
        SceneSpec scene = testing::unitBallScene(2, res, 30, 0);
        Progress quiet = Progress::silent();
        const BasisCache basis = computeBasis(scene, quiet);
        const size_t n = 30;
        ASSERT_EQ(basis.coefficients.packed.size(), packedSize(n));
        double typical = 0.0, self = 0.0;
        const auto& c = basis.coefficients.packed;
        for (double x : c) typical += std::abs(x);
        typical /= double(c.size());
        // C[m][k][k] = −C[k][k][m]: for m < k it is stored as pair (m, k) at i = k.
        for (size_t m = 0; m < n; ++m)
            for (size_t k = 0; k < n; ++k)
                if (m != k)
                    self = std::max(self, std::abs(m < k ? c[packedIndex(n, m, k, k)]
                                                         : c[packedIndex(n, k, k, m)]));
        const double ratio = self / typical;
        std::printf("disk %d²: max self-interaction / mean |C| = %.3e\n", res, ratio);
        if (previous > 0.0) {
            EXPECT_GT(previous / ratio, 3.0);
        }
        previous = ratio;
    }
}

}  // namespace
}  // namespace modeflow
