/// @file SurfaceBasis.cpp

#include "precompute/surface/SurfaceBasis.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "engine/core/Error.h"
#include "precompute/solve/SpectralBasis.h"

namespace modeflow {
namespace {

using Sparse = SurfaceDec::Sparse;

/// The two triangles of each edge: `left` runs along it from its lower to its higher vertex
/// (its interior lies to the edge's left), `right` the other way.
struct EdgeSides {
    std::vector<int> left, right;
};

EdgeSides edgeSides(const SurfaceTopology& top) {
    EdgeSides sides{std::vector<int>(top.edges.size(), -1), std::vector<int>(top.edges.size(), -1)};
    for (std::size_t t = 0; t < top.triangleEdges.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k)
            (top.triangleEdgeSigns[t][k] > 0 ? sides.left
                                             : sides.right)[std::size_t(top.triangleEdges[t][k])] =
                int(t);
    return sides;
}

/// Closed, non-exact 1-cochains (β1 of them), one per edge left over by a spanning tree of the
/// vertices and a spanning tree of the triangles across the remaining edges: the unit flux
/// along the dual loop through that edge and the triangle tree. Each triangle's net inflow is 0.
Eigen::MatrixXd cohomologyGenerators(const SurfaceDec& dec) {
    const SurfaceTopology& top = dec.topology;
    const std::size_t vertices = std::size_t(dec.star0.size()), edges = top.edges.size(),
                      triangles = top.triangleEdges.size();
    std::vector<std::vector<int>> vertexEdges(vertices);
    for (std::size_t e = 0; e < edges; ++e)
        for (int v : top.edges[e]) vertexEdges[std::size_t(v)].push_back(int(e));
    std::vector<bool> primalTree(edges, false), reached(vertices, false);
    for (std::size_t root = 0; root < vertices; ++root) {
        if (reached[root]) continue;
        reached[root] = true;
        std::deque<int> queue{int(root)};
        while (!queue.empty()) {
            const int v = queue.front();
            queue.pop_front();
            for (int e : vertexEdges[std::size_t(v)]) {
                const int w = top.edges[std::size_t(e)][0] == v ? top.edges[std::size_t(e)][1]
                                                                : top.edges[std::size_t(e)][0];
                if (reached[std::size_t(w)]) continue;
                reached[std::size_t(w)] = true;
                primalTree[std::size_t(e)] = true;
                queue.push_back(w);
            }
        }
    }
    const EdgeSides sides = edgeSides(top);
    std::vector<int> parent(triangles, -1), parentEdge(triangles, -1);
    std::vector<bool> dualTree(edges, false), visited(triangles, false);
    for (std::size_t root = 0; root < triangles; ++root) {
        if (visited[root]) continue;
        visited[root] = true;
        std::deque<int> queue{int(root)};
        while (!queue.empty()) {
            const int t = queue.front();
            queue.pop_front();
            for (int e : top.triangleEdges[std::size_t(t)]) {
                if (primalTree[std::size_t(e)]) continue;
                const int u = sides.left[std::size_t(e)] == t ? sides.right[std::size_t(e)]
                                                              : sides.left[std::size_t(e)];
                if (visited[std::size_t(u)]) continue;
                visited[std::size_t(u)] = true;
                dualTree[std::size_t(e)] = true;
                parent[std::size_t(u)] = t;
                parentEdge[std::size_t(u)] = e;
                queue.push_back(u);
            }
        }
    }
    std::vector<int> leftOver;
    for (std::size_t e = 0; e < edges; ++e)
        if (!primalTree[e] && !dualTree[e]) leftOver.push_back(int(e));
    const int expected = top.harmonicCount(int(vertices));
    if (int(leftOver.size()) != expected)
        throw Error("surface basis: the tree-cotree decomposition left " +
                    std::to_string(leftOver.size()) +
                    " edges, but the Euler characteristic asks for " + std::to_string(expected));

    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(Eigen::Index(edges), Eigen::Index(leftOver.size()));
    for (std::size_t g = 0; g < leftOver.size(); ++g) {
        auto column = c.col(Eigen::Index(g));
        // A unit flux across e into triangle `into`: positive towards the edge's left.
        const auto cross = [&](int e, int into) {
            column[e] += sides.left[std::size_t(e)] == into ? 1.0 : -1.0;
        };
        const int e = leftOver[g];
        const int from = sides.left[std::size_t(e)], to = sides.right[std::size_t(e)];
        cross(e, to);
        for (int t = to; parent[std::size_t(t)] >= 0; t = parent[std::size_t(t)])
            cross(parentEdge[std::size_t(t)], parent[std::size_t(t)]);
        for (int t = from; parent[std::size_t(t)] >= 0; t = parent[std::size_t(t)])
            cross(parentEdge[std::size_t(t)], t);
    }
    return c;
}

/// Solves L ψ = b for every column of b (each summing to zero over every component), with ψ
/// pinned to 0 at one vertex per component, where L is positive definite.
Eigen::MatrixXd solvePinnedLaplacian(const SurfaceDec& dec, const Eigen::MatrixXd& b) {
    const Eigen::Index n = dec.star0.size();
    std::vector<bool> pinned(std::size_t(n), false), reached(std::size_t(n), false);
    std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(n));
    for (const auto& [a, c] : dec.topology.edges) {
        neighbours[std::size_t(a)].push_back(c);
        neighbours[std::size_t(c)].push_back(a);
    }
    for (Eigen::Index root = 0; root < n; ++root) {
        if (reached[std::size_t(root)]) continue;
        pinned[std::size_t(root)] = true;
        std::vector<int> stack{int(root)};
        reached[std::size_t(root)] = true;
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            for (int w : neighbours[std::size_t(v)])
                if (!reached[std::size_t(w)]) reached[std::size_t(w)] = true, stack.push_back(w);
        }
    }
    std::vector<Eigen::Triplet<double>> keep;
    Eigen::Index kept = 0;
    for (Eigen::Index v = 0; v < n; ++v)
        if (!pinned[std::size_t(v)]) keep.emplace_back(v, kept++, 1.0);
    Sparse select(n, kept);
    select.setFromTriplets(keep.begin(), keep.end());
    const Sparse reduced = Sparse(select.transpose() * dec.laplacian() * select);
    Eigen::SimplicialLDLT<Sparse> solver(reduced);
    if (solver.info() != Eigen::Success)
        throw Error(
            "surface basis: the Laplace–Beltrami operator could not be factorized for the harmonic "
            "fields");
    return select * Eigen::MatrixXd(solver.solve(select.transpose() * b));
}

}  // namespace

Eigen::MatrixXd harmonicForms(const SurfaceDec& dec) {
    const Eigen::MatrixXd c = cohomologyGenerators(dec);
    if (c.cols() == 0) return c;
    const Eigen::MatrixXd rhs = dec.d0.transpose() * (dec.star1.asDiagonal() * c);
    Eigen::MatrixXd h = c - dec.d0 * solvePinnedLaplacian(dec, rhs);
    // The Gram matrix is positive definite: on closed forms ⋆1 is the L² product (SurfaceDec.h).
    const Eigen::MatrixXd gram = h.transpose() * dec.star1.asDiagonal() * h;
    const Eigen::LLT<Eigen::MatrixXd> llt(gram);
    if (llt.info() != Eigen::Success)
        throw Error("surface basis: the harmonic fields are not independent");
    return llt.matrixU().solve<Eigen::OnTheRight>(h);
}

SurfaceBasisResult solveSurfaceBasis(const SurfaceDec& dec, const std::vector<ModeRange>& ranges,
                                     int scalarModes, const SolveProgress& progress) {
    const int vertices = int(dec.star0.size());
    const int components = dec.topology.components;
    const int harmonic = dec.topology.harmonicCount(vertices);
    int highest = 0;
    for (const ModeRange& r : ranges) highest = std::max(highest, r.last);
    const int coExact = vertices - components;
    if (highest > coExact + harmonic)
        throw Error("[basis]: asked for divergence-free mode " + std::to_string(highest) +
                    " but the surface holds only " + std::to_string(coExact + harmonic) +
                    " divergence-free fields (" + std::to_string(harmonic) +
                    " harmonic); use a finer mesh");
    if (scalarModes > coExact)
        throw Error("[basis].scalar_modes = " + std::to_string(scalarModes) +
                    ": the surface holds only " + std::to_string(coExact) +
                    " non-constant scalar modes; use a finer mesh");

    SurfaceBasisResult r;
    r.omittedConstants = components;
    const int wanted = std::max(highest - harmonic, scalarModes);
    Eigen::VectorXd lambda;
    Eigen::MatrixXd psi(vertices, 0);
    if (wanted > 0) {
        // λ₁ of a round sphere of this area is 8π/A; the shift only has to lie below 0.
        const double scale = 8.0 * M_PI / dec.totalArea();
        const EigenRequest request{wanted + components, -1e-2 * scale, 1e-12,
                                   "Laplace–Beltrami eigensolve", progress};
        EigenPairs pairs =
            lowestEigenpairs(dec.laplacian(), dec.star0, request, EigensolverChoice::Spectra);
        r.stats = pairs.stats;
        lambda = pairs.values.tail(wanted);
        psi = pairs.vectors.rightCols(wanted);
    }
    r.scalarEigenvalues = lambda.head(scalarModes);
    r.scalarModes = psi.leftCols(scalarModes);

    const Eigen::MatrixXd h = harmonicForms(dec);
    std::vector<int> keep;
    for (const ModeRange& range : ranges)
        for (int m = range.first; m <= range.last; ++m) keep.push_back(m);
    r.velocityEigenvalues.resize(Eigen::Index(keep.size()));
    r.velocityModes.resize(Eigen::Index(dec.topology.edges.size()), Eigen::Index(keep.size()));
    for (std::size_t i = 0; i < keep.size(); ++i) {
        const int m = keep[i];
        const auto at = Eigen::Index(i);
        if (m <= harmonic) {
            r.velocityEigenvalues[at] = 0.0;
            r.velocityModes.col(at) = h.col(m - 1);
            ++r.harmonicCount;
        } else {
            const Eigen::Index s = m - harmonic - 1;
            r.velocityEigenvalues[at] = lambda[s];
            r.velocityModes.col(at) = dec.d0 * psi.col(s) / std::sqrt(lambda[s]);
        }
        r.modeNumbers.push_back(m);
    }
    return r;
}

}  // namespace modeflow
