#include "precompute/solve/SpectralBasis.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "engine/core/Error.h"
#include "engine/core/KappaSquared.h"
#include "precompute/dec/FluidComponents.h"
#include "precompute/solve/Laplacians.h"
#include "precompute/solve/ProcessGroup.h"
#include "precompute/solve/SlicedEigensolver.h"

namespace modeflow {
namespace {

std::string plural(std::int64_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

EigenPairs lowestEigenpairs(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                            const EigenRequest& request, EigensolverChoice choice) {
    switch (chooseEigenMethod(k.rows(), request.count, choice, currentProcessGroup().size)) {
        case EigenMethod::Slicing:
            return slicedEigenpairs(k, m, request);
        case EigenMethod::BlockLanczos:
            return smallestEigenpairs(k, m, request, KrylovMethod::BlockLanczos);
        case EigenMethod::Lanczos:
            return smallestEigenpairs(k, m, request, KrylovMethod::Lanczos);
        case EigenMethod::Dense:
            break;
    }
    const Eigen::VectorXd s = m.cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd a = s.asDiagonal() * Eigen::MatrixXd(k) * s.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a);
    EigenPairs out;
    out.values = eig.eigenvalues().head(request.count);
    out.vectors = s.asDiagonal() * eig.eigenvectors().leftCols(request.count);
    return out;
}

double domainMeasure(const Eigen::VectorXd& cellStar) {
    return cellStar.cwiseInverse().sum();
}

double referenceEigenvalue(const GridSpec& grid) {
    double l = 0.0;
    for (int a = 0; a < grid.dim; ++a) l = std::max(l, grid.boundsMax[a] - grid.boundsMin[a]);
    return (M_PI / l) * (M_PI / l);
}

int closedComponents(const CutCellDec& dec) {
    return fluidComponents(dec).closedCount();
}

std::int64_t divergenceFreeDimension(const CutCellDec& dec) {
    return dec.faces.size() - dec.cells.size() + closedComponents(dec);
}

namespace {

/// An eigenvector's sign is the solver's accident (its start vector, BLAS's threads, the
/// compiler's rounding), and a scene that sets modal amplitudes, or a harmonic field's flow,
/// would run the other way on another machine. Each column is turned so that its first entry of
/// largest magnitude (to 1e-6 of it, so that round-off cannot pick between mirror images) is
/// positive.
void orientColumns(Eigen::MatrixXd& vectors) {
    for (Eigen::Index c = 0; c < vectors.cols(); ++c) {
        auto column = vectors.col(c);
        const double largest = column.cwiseAbs().maxCoeff();
        Eigen::Index at = 0;
        while (std::abs(column[at]) < (1.0 - 1e-6) * largest) ++at;
        if (column[at] < 0.0) column = -column;
    }
}

ScalarBasisResult fromPairs(EigenPairs pairs, int skip) {
    orientColumns(pairs.vectors);
    ScalarBasisResult r;
    const int count = int(pairs.values.size()) - skip;
    r.eigenvalues = pairs.values.tail(count);
    r.modes = pairs.vectors.rightCols(count);
    r.omittedConstants = skip;
    r.stats = pairs.stats;
    return r;
}

/// λ_N of the div-free spectrum by Weyl's law (2D: N ≈ |Ω|λ/4π; 3D, two polarizations:
/// N ≈ |Ω|λ^{3/2}/3π²), used to pick a first penalty and where slicing's first interval ends.
double weylEstimate(int dim, int n, double measure) {
    if (dim == 2) return 4.0 * M_PI * n / measure;
    return std::pow(3.0 * M_PI * M_PI * n / measure, 2.0 / 3.0);
}

/// λ_N of a scalar Laplacian by Weyl's law (2D: N ≈ |Ω|λ/4π; 3D: N ≈ |Ω|λ^{3/2}/6π²).
double scalarWeylEstimate(int dim, int n, double measure) {
    if (dim == 2) return 4.0 * M_PI * n / measure;
    return std::pow(6.0 * M_PI * M_PI * n / measure, 2.0 / 3.0);
}

EigenRequest scalarRequest(int count, const GridSpec& grid, const Eigen::VectorXd& cellStar,
                           const char* what, const SolveProgress& progress,
                           const IntervalCheckpoints& checkpoints) {
    EigenRequest request{
        count, -1e-2 * referenceEigenvalue(grid), 1e-12, what, progress, grid.anyPeriodic()};
    request.estimate = scalarWeylEstimate(grid.dim, count, domainMeasure(cellStar));
    request.spectralDimension = grid.dim;
    request.checkpoints = checkpoints;
    return request;
}

/// Replaces the columns of `pairs` by exactly divergence-free Ritz vectors of the unpenalized L2
/// in their span: ⋆-orthogonal Helmholtz projection Ψ − ⋆⁻¹dᵀ(d⋆⁻¹dᵀ)⁺dΨ (twice, for round-off),
/// then the small generalized eigenproblem of L2 and ⋆ on the projected vectors.
void projectAndRefine(const CutCellDec& dec, EigenPairs& pairs) {
    using ColMatrix = Eigen::SparseMatrix<double>;
    const ColMatrix d = ColMatrix(dec.div);
    const Eigen::VectorXd massInverse = dec.faceStar.cwiseInverse();
    ColMatrix poisson = d * massInverse.asDiagonal() * d.transpose();
    // Constants per component are the null space; dΨ is orthogonal to them, so a tiny diagonal
    // shift changes nothing the projection uses.
    const double shift = 1e-12 * poisson.diagonal().cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < poisson.rows(); ++i) poisson.coeffRef(i, i) += shift;
    Eigen::SimplicialLDLT<ColMatrix> solver(poisson);
    if (solver.info() != Eigen::Success)
        throw Error("velocity eigensolve: the divergence projection could not be factorized");
    Eigen::MatrixXd& v = pairs.vectors;
    for (int pass = 0; pass < 2; ++pass) {
        const Eigen::MatrixXd p = solver.solve(d * v);
        v -= massInverse.asDiagonal() * (d.transpose() * p);
    }
    const ColMatrix k = velocityLaplacian(dec, 0.0);
    const Eigen::MatrixXd kr = v.transpose() * (k * v);
    const Eigen::MatrixXd mr = v.transpose() * dec.faceStar.asDiagonal() * v;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(kr, mr);
    pairs.values = ritz.eigenvalues();
    v = v * ritz.eigenvectors();
}

}  // namespace

ScalarBasisResult solveNeumannScalarBasis(const CutCellDec& dec, int count,
                                          const SolveProgress& progress, EigensolverChoice choice,
                                          const IntervalCheckpoints& checkpoints) {
    const int constants = closedComponents(dec);
    const std::int64_t available = dec.cells.size() - constants;
    if (count > available)
        throw Error("[basis].scalar_modes = " + std::to_string(count) + ": the domain holds only " +
                    plural(available, "non-constant Neumann scalar mode"));
    const EigenRequest request =
        scalarRequest(count + constants, dec.grid, dec.cellStar, "scalar (Neumann) eigensolve",
                      progress, checkpoints);
    return fromPairs(lowestEigenpairs(neumannScalarLaplacian(dec), dec.cellStar, request, choice),
                     constants);
}

ScalarBasisResult solveDirichletScalarBasis(const DirichletScalarDec& dec, int count,
                                            const SolveProgress& progress, EigensolverChoice choice,
                                            const IntervalCheckpoints& checkpoints) {
    if (count > dec.cells.size())
        throw Error("[basis].scalar_modes = " + std::to_string(count) + ": the domain holds only " +
                    plural(dec.cells.size(), "Dirichlet scalar mode"));
    const EigenRequest request = scalarRequest(
        count, dec.grid, dec.cellStar, "scalar (Dirichlet) eigensolve", progress, checkpoints);
    return fromPairs(lowestEigenpairs(dirichletScalarLaplacian(dec), dec.cellStar, request, choice),
                     0);
}

VelocityBasisResult solveVelocityBasis(const CutCellDec& dec, const std::vector<ModeRange>& ranges,
                                       double firstNeumannEigenvalue, double domainMeasure,
                                       const SolveProgress& progress, EigensolverChoice choice,
                                       const IntervalCheckpoints& checkpoints) {
    int highest = 0;
    for (const ModeRange& r : ranges) highest = std::max(highest, r.last);
    const std::int64_t available = divergenceFreeDimension(dec);
    if (highest > available)
        throw Error("[basis]: asked for divergence-free mode " + std::to_string(highest) +
                    " but the domain holds only " + plural(available, "divergence-free field") +
                    " at this resolution");

    const double mu1 = firstNeumannEigenvalue;
    const bool noSlip = dec.wall == WallKind::NoSlip;
    // No-slip walls break the exact Hodge splitting (the wall vorticity also sees gradients), so
    // the penalty only approximates the div-free constraint, to O(1/s): make s large and finish
    // with an exact projection and a Rayleigh–Ritz step.
    double penalty = std::max(1.0, 2.0 * weylEstimate(dec.grid.dim, highest, domainMeasure) / mu1) *
                     (noSlip ? 1e4 : 1.0);
    EigenRequest request{highest,  -1e-2 * referenceEigenvalue(dec.grid),
                         1e-12,    "velocity eigensolve",
                         progress, dec.grid.anyPeriodic()};
    request.estimate = weylEstimate(dec.grid.dim, highest, domainMeasure);
    request.spectralDimension = dec.grid.dim;
    request.checkpoints = checkpoints;
    EigenPairs pairs;
    SolverStats stats;
    for (int attempt = 0;; ++attempt) {
        pairs = lowestEigenpairs(velocityLaplacian(dec, penalty), dec.faceStar, request, choice);
        stats += pairs.stats;
        const double top = pairs.values[highest - 1];
        // Every gradient eigenvalue of the penalized operator is at least (1+s)μ₁², so when the
        // top computed value is below it, all computed modes are divergence-free.
        if (noSlip || top < 0.999 * (1.0 + penalty) * mu1) break;
        if (attempt == 3)
            throw Error(
                "velocity eigensolve: gradient fields stayed in the low spectrum after "
                "raising the grad-div penalty to " +
                std::to_string(penalty));
        penalty = 4.0 * top / mu1;
    }

    if (noSlip) projectAndRefine(dec, pairs);
    orientColumns(pairs.vectors);
    // A harmonic field's κ² is exactly 0; the solve returns it as round-off of either sign. The
    // first non-zero κ² is the smallest above round-off of (π/L)², or (π/L)² itself when every
    // computed mode is harmonic.
    pairs.values = checkedKappaSquared(
        pairs.values, firstNonZeroKappaSquared(pairs.values, referenceEigenvalue(dec.grid)),
        request.what);

    VelocityBasisResult r;
    r.penalty = penalty;
    r.stats = stats;
    std::vector<Eigen::Index> keep;
    for (const ModeRange& range : ranges)
        for (int m = range.first; m <= range.last; ++m) keep.push_back(m - 1);
    r.eigenvalues.resize(Eigen::Index(keep.size()));
    r.modes.resize(pairs.vectors.rows(), Eigen::Index(keep.size()));
    for (size_t i = 0; i < keep.size(); ++i) {
        r.eigenvalues[Eigen::Index(i)] = pairs.values[keep[i]];
        r.modes.col(Eigen::Index(i)) = pairs.vectors.col(keep[i]);
        r.modeNumbers.push_back(int(keep[i]) + 1);
        if (pairs.values[keep[i]] == 0.0) ++r.harmonicCount;
    }
    return r;
}

}  // namespace modeflow
