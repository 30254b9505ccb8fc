// 3D structural coefficients converge at second order: free-slip box fields u = curl(φ e_E),
// sampled as face fluxes, against a Gauss quadrature of ∫ ω_i · (u_k × u_j).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "engine/core/PackedLayout.h"
#include "engine/core/Vec3Math.h"
#include "precompute/coefficients/CoefficientAssembly.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

const std::array<double, 3> kSides = {1.2, 1.0, 0.9};

/// φ = Π_d f_d(x_d) with f_d = sin or cos(k_d π x_d / L_d); sin on the two axes other than E,
/// cos along E, so u = ∇φ × e_E has no normal flow and free-slip derivatives on every wall.
struct CurlField {
    int axis;                 // E
    std::array<int, 3> wave;  // k_d

    double factor(int d, double x, int order) const {
        const double w = wave[d] * M_PI / kSides[d];
        const bool isSin = d != axis;
        // derivatives of sin: sin, cos, -sin ...; of cos: cos, -sin, -cos ...
        const int phase = (isSin ? 0 : 1) + order;
        const double s = std::sin(w * x), c = std::cos(w * x);
        const double values[4] = {s, c, -s, -c};
        return std::pow(w, order) * values[phase % 4];
    }
    double partial(const Vec3& p, std::array<int, 3> alpha) const {
        return factor(0, p[0], alpha[0]) * factor(1, p[1], alpha[1]) * factor(2, p[2], alpha[2]);
    }
    Vec3 velocity(const Vec3& p) const {  // ∇φ × e_E
        const Vec3 g = {partial(p, {1, 0, 0}), partial(p, {0, 1, 0}), partial(p, {0, 0, 1})};
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        Vec3 u{0.0, 0.0, 0.0};
        u[b] = g[c];
        u[c] = -g[b];
        return u;
    }
    Vec3 vorticity(const Vec3& p) const {  // ∇(∂_E φ) − Δφ e_E
        Vec3 w{0.0, 0.0, 0.0};
        for (int d = 0; d < 3; ++d) {
            std::array<int, 3> alpha{0, 0, 0};
            alpha[axis] += 1;
            alpha[d] += 1;
            w[d] = partial(p, alpha);
        }
        for (int d = 0; d < 3; ++d) {
            std::array<int, 3> alpha{0, 0, 0};
            alpha[d] = 2;
            w[axis] -= partial(p, alpha);
        }
        return w;
    }
};

const std::vector<CurlField> kFields = {
    {2, {1, 1, 1}}, {0, {1, 1, 1}}, {1, {1, 2, 1}}, {2, {2, 1, 0}}};

const double kNode[] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                        0.8611363115940526};
const double kWeight[] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                          0.3478548451374538};

double continuumCoefficient(const CurlField& k, const CurlField& i, const CurlField& j) {
    const int panels = 6;
    double sum = 0.0;
    for (int px = 0; px < panels; ++px)
        for (int py = 0; py < panels; ++py)
            for (int pz = 0; pz < panels; ++pz)
                for (int a = 0; a < 4; ++a)
                    for (int b = 0; b < 4; ++b)
                        for (int c = 0; c < 4; ++c) {
                            const Vec3 p = {kSides[0] * (px + 0.5 * (kNode[a] + 1)) / panels,
                                            kSides[1] * (py + 0.5 * (kNode[b] + 1)) / panels,
                                            kSides[2] * (pz + 0.5 * (kNode[c] + 1)) / panels};
                            const double w = kWeight[a] * kWeight[b] * kWeight[c] * 0.125 *
                                             kSides[0] * kSides[1] * kSides[2] /
                                             (panels * panels * panels);
                            const Vec3 uxu = cross(k.velocity(p), j.velocity(p));
                            const Vec3 om = i.vorticity(p);
                            sum += w * (om[0] * uxu[0] + om[1] * uxu[1] + om[2] * uxu[2]);
                        }
    return sum;
}

std::vector<double> discreteCoefficients(int resolution) {
    const std::array<int, 3> res = {int(std::lround(kSides[0] * resolution)), resolution,
                                    int(std::lround(kSides[2] * resolution))};
    const SceneSpec scene =
        testing::gridScene(res, {0.0, 0.0, 0.0}, {kSides[0], kSides[1], kSides[2]}, 3);
    const CubicalComplex cx(scene.grid);
    const Domain domain({}, 3, 1.0);
    const CutCellMeasures measures = measureCutCells(cx, domain, BoundaryTreatment::CutCell, 1);
    const CutCellDec dec = buildCutCellDec(cx, measures, WallKind::FreeSlip);
    Eigen::MatrixXd modes(dec.faces.size(), Eigen::Index(kFields.size()));
    for (std::int64_t f = 0; f < dec.faces.size(); ++f) {
        const Element e = cx.element(2, dec.faces.toGlobal[f]);
        const int normal = __builtin_ctz(7u & ~e.axes);
        const int s = (normal + 1) % 3, t = (normal + 2) % 3;
        const double hs = scene.grid.spacing(s), ht = scene.grid.spacing(t);
        for (size_t m = 0; m < kFields.size(); ++m) {
            double flux = 0.0;  // 4×4 Gauss over the face: exact enough (1e-10) for the test
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) {
                    Vec3 p;
                    p[normal] = e.pos[normal] * scene.grid.spacing(normal);
                    p[s] = (e.pos[s] + 0.5 * (kNode[a] + 1)) * hs;
                    p[t] = (e.pos[t] + 0.5 * (kNode[b] + 1)) * ht;
                    flux +=
                        kWeight[a] * kWeight[b] * 0.25 * hs * ht * kFields[m].velocity(p)[normal];
                }
            modes(f, Eigen::Index(m)) = flux;
        }
    }
    return assembleStructuralCoefficients(cx, measures, dec, modes);
}

TEST(CoefficientAssembly3D, BoxCoefficientsConvergeQuadratically) {
    const size_t n = kFields.size();
    std::vector<double> exact(packedSize(n));
    double scale = 0.0;
    for (size_t k = 0; k < n; ++k)
        for (size_t j = k + 1; j < n; ++j)
            for (size_t i = 0; i < n; ++i) {
                exact[packedIndex(n, k, i, j)] =
                    continuumCoefficient(kFields[k], kFields[i], kFields[j]);
                scale = std::max(scale, std::abs(exact[packedIndex(n, k, i, j)]));
            }
    ASSERT_GT(scale, 1.0) << "the chosen fields must interact";
    double previous = 0.0;
    for (int res : {8, 16, 32}) {
        const std::vector<double> c = discreteCoefficients(res);
        double err = 0.0;
        for (size_t p = 0; p < c.size(); ++p) err = std::max(err, std::abs(c[p] - exact[p]));
        err /= scale;
        std::printf("box 3D, %d cells across: max |C − C_exact| / max |C_exact| = %.3e", res, err);
        if (previous > 0.0) std::printf("  (order %.2f)", std::log2(previous / err));
        std::printf("\n");
        if (previous > 0.0) {
            EXPECT_GT(previous / err, 3.3) << "not second order at " << res;
        }
        previous = err;
    }
}

}  // namespace
}  // namespace modeflow
