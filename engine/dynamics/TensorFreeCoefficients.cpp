#include "engine/dynamics/TensorFreeCoefficients.h"

#include <algorithm>
#include <string>

#include "engine/core/Error.h"
#include "engine/dynamics/QuadratureSampling.h"

namespace modeflow {
namespace {

/// Rows [first, first + count) of M·Ψ, column by column (each column of Ψ is contiguous).
Eigen::MatrixXd sampleModes(const SparseRows& m, std::int64_t first, std::int64_t count,
                            const Eigen::MatrixXd& modes) {
    Eigen::MatrixXd out(count, modes.cols());
    for (Eigen::Index j = 0; j < modes.cols(); ++j)
        sampleRows(m, first, modes.col(j).data(), out.col(j).data(), count);
    return out;
}

void requireRows(const SparseRows& m, std::int64_t rows, Eigen::Index faces, const char* what) {
    if (m.rows() != rows)
        throw Error(std::string("tensor-free coefficients: the quadrature's ") + what + " has " +
                    std::to_string(m.rows()) + " rows, the curl " + std::to_string(rows));
    for (std::int32_t c : m.column)
        if (c < 0 || c >= faces)
            throw Error(std::string("tensor-free coefficients: the quadrature's ") + what +
                        " references face " + std::to_string(c) + " of " + std::to_string(faces));
}

/// Bytes of the element samples linearize holds at once (three blocks of elements × N).
constexpr std::size_t kBlockBytes = std::size_t(32) << 20;

}  // namespace

TensorFreeCoefficients::TensorFreeCoefficients(const Eigen::MatrixXd& modes,
                                               const BasisCache::Quadrature& quadrature)
    : mModes(modes), mQuadrature(quadrature) {
    if (modes.cols() < 1) throw Error("tensor-free coefficients: the basis has no modes");
    const std::int64_t rows = quadrature.curl.rows();
    requireRows(quadrature.curl, rows, modes.rows(), "curl");
    requireRows(quadrature.velocityB, rows, modes.rows(), "first velocity component");
    requireRows(quadrature.velocityC, rows, modes.rows(), "second velocity component");
}

std::size_t TensorFreeCoefficients::storedBytes() const {
    return 2 * std::size_t(mModes.size()) * sizeof(double) + mQuadrature.curl.bytes() +
           mQuadrature.velocityB.bytes() + mQuadrature.velocityC.bytes();
}

Eigen::MatrixXd TensorFreeCoefficients::fluxes(const Eigen::VectorXd& a,
                                               const Eigen::VectorXd& b) const {
    if (a == b) return mModes * a;
    Eigen::MatrixXd ab(a.size(), 2);
    ab << a, b;
    return mModes * ab;
}

double TensorFreeCoefficients::entry(int k, int i, int j) const {
    const auto& q = mQuadrature;
    const Eigen::VectorXd omega = sample(q.curl, mModes.col(i));
    const Eigen::VectorXd pk = sample(q.velocityB, mModes.col(k)),
                          qk = sample(q.velocityC, mModes.col(k));
    const Eigen::VectorXd pj = sample(q.velocityB, mModes.col(j)),
                          qj = sample(q.velocityC, mModes.col(j));
    return omega.dot(pk.cwiseProduct(qj) - qk.cwiseProduct(pj));
}

void TensorFreeCoefficients::apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                   Eigen::VectorXd& out) const {
    checkSize("apply", a);
    checkSize("apply", b);
    const auto& q = mQuadrature;
    const Eigen::MatrixXd u = fluxes(a, b);
    const Eigen::VectorXd omega = sample(q.curl, u.col(0));
    const Eigen::VectorXd pb = sample(q.velocityB, u.col(u.cols() - 1));
    const Eigen::VectorXd qb = sample(q.velocityC, u.col(u.cols() - 1));
    Eigen::VectorXd g = Eigen::VectorXd::Zero(mModes.rows());
    addTransposed(q.velocityB, omega.cwiseProduct(qb), g);
    addTransposed(q.velocityC, -omega.cwiseProduct(pb), g);
    out.noalias() = mModes.transpose() * g;
}

void TensorFreeCoefficients::advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                                    Eigen::VectorXd& out) const {
    checkSize("advect", u);
    checkSize("advect", x);
    const auto& q = mQuadrature;
    const Eigen::MatrixXd f = fluxes(u, x);
    const Eigen::Index xc = f.cols() - 1;
    const Eigen::VectorXd pu = sample(q.velocityB, f.col(0)), qu = sample(q.velocityC, f.col(0));
    const Eigen::VectorXd px = sample(q.velocityB, f.col(xc)), qx = sample(q.velocityC, f.col(xc));
    Eigen::VectorXd g = Eigen::VectorXd::Zero(mModes.rows());
    addTransposed(q.curl, pu.cwiseProduct(qx) - qu.cwiseProduct(px), g);
    out.noalias() = mModes.transpose() * g;
}

void TensorFreeCoefficients::linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                       Eigen::MatrixXd& byI, Eigen::MatrixXd& byJ) const {
    // With P = BΨ, Q = QΨ, Ω = ΩΨ (elements × N):
    //   byI = X − Xᵀ, X = Pᵀ diag(ω_a) Q;   byJ = (Pᵀ diag(q_b) − Qᵀ diag(p_b)) Ω,
    // accumulated over blocks of elements so that only a block of P, Q, Ω is held.
    checkSize("linearize", a);
    checkSize("linearize", b);
    const auto& q = mQuadrature;
    const int n = size();
    const Eigen::MatrixXd u = fluxes(a, b);
    const Eigen::VectorXd omega = sample(q.curl, u.col(0));
    const Eigen::VectorXd pb = sample(q.velocityB, u.col(u.cols() - 1));
    const Eigen::VectorXd qb = sample(q.velocityC, u.col(u.cols() - 1));
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, n);
    byJ.setZero(n, n);
    const std::int64_t elements = q.curl.rows();
    const std::int64_t block = std::max<std::int64_t>(
        1, std::int64_t(kBlockBytes / (3 * sizeof(double) * std::size_t(n))));
    for (std::int64_t first = 0; first < elements; first += block) {
        const std::int64_t count = std::min(block, elements - first);
        const Eigen::MatrixXd p = sampleModes(q.velocityB, first, count, mModes);
        const Eigen::MatrixXd c = sampleModes(q.velocityC, first, count, mModes);
        const Eigen::MatrixXd w = sampleModes(q.curl, first, count, mModes);
        x.noalias() += p.transpose() * (omega.segment(first, count).asDiagonal() * c);
        const Eigen::MatrixXd mixed =
            qb.segment(first, count).asDiagonal() * p - pb.segment(first, count).asDiagonal() * c;
        byJ.noalias() += mixed.transpose() * w;
    }
    byI = x - x.transpose();
}

}  // namespace modeflow
