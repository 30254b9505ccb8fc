#pragma once
// Dense references on a whole grid box whose axes may be periodic, built directly from the MAC
// stencils with wrapped neighbours (the production cut-cell operators cannot wrap yet): the
// divergence, the velocity operator L2 = dᵀ⋆n d + ⋆(n−1) δ ⋆(n−2)⁻¹ δᵀ ⋆(n−1), the Neumann
// scalar operator, and the structural-coefficient quadrature of CoefficientAssembly.cpp with
// wrapped face look-ups. Small grids only (dense matrices).

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <Eigen/Dense>

#include "engine/core/MacGrid.h"
#include "engine/format/BasisCache.h"

namespace modeflow::testing {

class WholeBoxReference {
public:
    /// `cache` holds the grid and the face DOFs (fillWholeBoxDofs).
    explicit WholeBoxReference(const BasisCache& cache)
        : mCache(cache), mMac(MacGrid::fromSpec(cache.grid)) {
        for (std::size_t f = 0; f < cache.faces.size(); ++f) mDof[cache.faces[f]] = Eigen::Index(f);
        buildOperators();
    }

    const Eigen::MatrixXd& divergence() const { return mDiv; }
    const Eigen::MatrixXd& velocityLaplacian() const { return mL2; }
    const Eigen::MatrixXd& neumannLaplacian() const { return mL3; }

    /// The face DOF with normal `axis` at `pos` (wrapped along periodic axes), or −1 when the
    /// face is a wall or outside the grid.
    Eigen::Index face(int axis, std::array<int, 3> pos) const {
        const GridSpec& g = mCache.grid;
        for (int a = 0; a < g.dim; ++a) {
            const int n = g.resolution[a];
            if (g.isPeriodic(a))
                pos[a] = ((pos[a] % n) + n) % n;
            else if (pos[a] < 0 || pos[a] > n - (a == axis ? 0 : 1))
                return -1;
        }
        const auto it = mDof.find(mMac.faceIndex(axis, pos[0], pos[1], pos[2]));
        return it == mDof.end() ? -1 : it->second;
    }

    /// The interior vorticity elements: (axis a, position), 2D vertices as a = 2.
    std::vector<std::pair<int, std::array<int, 3>>> vorticityElements() const {
        const GridSpec& g = mCache.grid;
        std::vector<std::pair<int, std::array<int, 3>>> out;
        const std::vector<int> types = g.dim == 3 ? std::vector<int>{0, 1, 2} : std::vector<int>{2};
        for (int a : types) {
            std::array<int, 3> lo{0, 0, 0}, hi{1, 1, 1};
            for (int d = 0; d < g.dim; ++d) {
                lo[d] = d == a || g.isPeriodic(d) ? 0 : 1;
                hi[d] = g.resolution[d];
            }
            for (int z = lo[2]; z < hi[2]; ++z)
                for (int y = lo[1]; y < hi[1]; ++y)
                    for (int x = lo[0]; x < hi[0]; ++x) out.push_back({a, {x, y, z}});
        }
        return out;
    }

    /// C[k][i][j] (dense N³, index (k·N + i)·N + j) of the fluxes `modes`, by the quadrature of
    /// CoefficientAssembly.cpp: w_e ω_i (u_kb u_jc − u_kc u_jb) over the vorticity elements.
    std::vector<double> coefficients(const Eigen::MatrixXd& modes) const {
        const GridSpec& g = mCache.grid;
        const Eigen::Index n = modes.cols();
        std::vector<double> c(std::size_t(n * n * n), 0.0);
        for (const auto& [a, pos] : vorticityElements()) {
            const int b = (a + 1) % 3, cc = (a + 2) % 3;
            const double hb = g.spacing(b), hc = g.spacing(cc);
            const double weight = (g.dim == 3 ? g.spacing(a) : 1.0) * hb * hc;
            std::array<int, 3> minusB = pos, minusC = pos;
            --minusB[b];
            --minusC[cc];
            Eigen::VectorXd omega = Eigen::VectorXd::Zero(n), ub = omega, uc = omega;
            auto velocity = [&](Eigen::Index f, int axis) {
                return modes.row(f).transpose() / mMac.faceArea(axis);
            };
            const std::pair<Eigen::Index, double> circulation[4] = {{face(cc, pos), 1.0 / hb},
                                                                    {face(cc, minusB), -1.0 / hb},
                                                                    {face(b, pos), -1.0 / hc},
                                                                    {face(b, minusC), 1.0 / hc}};
            for (int t = 0; t < 4; ++t)
                if (circulation[t].first >= 0)
                    omega += circulation[t].second * velocity(circulation[t].first, t < 2 ? cc : b);
            for (Eigen::Index f : {face(b, pos), face(b, minusC)})
                if (f >= 0) ub += 0.5 * velocity(f, b);
            for (Eigen::Index f : {face(cc, pos), face(cc, minusB)})
                if (f >= 0) uc += 0.5 * velocity(f, cc);
            for (Eigen::Index k = 0; k < n; ++k)
                for (Eigen::Index j = 0; j < n; ++j) {
                    const double r = weight * (ub[k] * uc[j] - uc[k] * ub[j]);
                    if (r == 0.0) continue;
                    for (Eigen::Index i = 0; i < n; ++i)
                        c[std::size_t((k * n + i) * n + j)] += omega[i] * r;
                }
        }
        return c;
    }

private:
    void buildOperators() {
        const GridSpec& g = mCache.grid;
        const auto faces = Eigen::Index(mCache.faces.size());
        const Eigen::Index cells = mMac.cellCount();
        mDiv = Eigen::MatrixXd::Zero(cells, faces);
        for (int z = 0; z < mMac.cells[2]; ++z)
            for (int y = 0; y < mMac.cells[1]; ++y)
                for (int x = 0; x < mMac.cells[0]; ++x)
                    for (int a = 0; a < g.dim; ++a) {
                        std::array<int, 3> up{x, y, z};
                        ++up[a];
                        const Eigen::Index row = mMac.cellIndex(x, y, z);
                        const Eigen::Index hi = face(a, up), lo = face(a, {x, y, z});
                        if (hi >= 0) mDiv(row, hi) += 1.0;
                        if (lo >= 0) mDiv(row, lo) -= 1.0;
                    }
        const auto elements = vorticityElements();
        Eigen::MatrixXd curl = Eigen::MatrixXd::Zero(Eigen::Index(elements.size()), faces);
        Eigen::VectorXd starInverse(Eigen::Index(elements.size()));
        for (std::size_t e = 0; e < elements.size(); ++e) {
            const auto& [a, pos] = elements[e];
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            std::array<int, 3> minusB = pos, minusC = pos;
            --minusB[b];
            --minusC[c];
            const std::pair<Eigen::Index, double> sides[4] = {{face(c, pos), 1.0},
                                                              {face(c, minusB), -1.0},
                                                              {face(b, pos), -1.0},
                                                              {face(b, minusC), 1.0}};
            for (const auto& [f, s] : sides)
                if (f >= 0) curl(Eigen::Index(e), f) += s;
            starInverse[Eigen::Index(e)] =
                (g.dim == 3 ? g.spacing(a) : 1.0) / (g.spacing(b) * g.spacing(c));
        }
        const Eigen::VectorXd& star2 = mCache.faceStar;
        const Eigen::VectorXd& star3 = mCache.cellStar;
        mL2 = mDiv.transpose() * star3.asDiagonal() * mDiv + star2.asDiagonal() * curl.transpose() *
                                                                 starInverse.asDiagonal() * curl *
                                                                 star2.asDiagonal();
        mL3 = star3.asDiagonal() * mDiv * star2.cwiseInverse().asDiagonal() * mDiv.transpose() *
              star3.asDiagonal();
    }

    const BasisCache& mCache;
    MacGrid mMac;
    std::map<std::int64_t, Eigen::Index> mDof;
    Eigen::MatrixXd mDiv, mL2, mL3;
};

}  // namespace modeflow::testing
