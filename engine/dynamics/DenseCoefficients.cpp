#include "engine/dynamics/DenseCoefficients.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/ParallelRows.h"

namespace modeflow {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Bytes of coefficient rows the linearization handles at once (a fraction of L1/L2).
constexpr std::size_t kChunkBytes = 32 * 1024;

}  // namespace

DenseCoefficients::DenseCoefficients(int n, std::vector<double> packed)
    : mN(n), mPacked(std::move(packed)) {
    if (n < 1)
        throw Error("dense coefficients: the mode count must be positive, got " +
                    std::to_string(n));
    if (mPacked.size() != packedSize(n)) {
        throw Error("dense coefficients: " + std::to_string(n) + " modes need " +
                    std::to_string(packedSize(n)) + " packed values (N²(N−1)/2), got " +
                    std::to_string(mPacked.size()));
    }
    mPairK.reserve(pairCount(n));
    mPairJ.reserve(pairCount(n));
    for (int k = 0; k < n; ++k) {
        for (int j = k + 1; j < n; ++j) {
            mPairK.push_back(k);
            mPairJ.push_back(j);
        }
    }
}

DenseCoefficients DenseCoefficients::fromFull(int n, std::span<const double> full,
                                              double tolerance) {
    const std::size_t un = std::size_t(std::max(n, 0));
    if (n < 1 || full.size() != un * un * un) {
        throw Error("dense coefficients: a full array for " + std::to_string(n) +
                    " modes needs N³ values, got " + std::to_string(full.size()));
    }
    const auto at = [&](std::size_t k, std::size_t i, std::size_t j) {
        return full[(k * un + i) * un + j];
    };
    std::vector<double> packed(packedSize(un));
    double largest = 0.0, deviation = 0.0;
    for (std::size_t k = 0; k < un; ++k) {
        for (std::size_t i = 0; i < un; ++i) {
            for (std::size_t j = k; j < un; ++j) {
                largest = std::max({largest, std::abs(at(k, i, j)), std::abs(at(j, i, k))});
                deviation = std::max(deviation, std::abs(at(k, i, j) + at(j, i, k)));
                if (j > k) packed[packedIndex(un, k, i, j)] = at(k, i, j);
            }
        }
    }
    DenseCoefficients result(n, std::move(packed));
    result.mAntisymmetryError = largest > 0.0 ? deviation / largest : 0.0;
    if (!(result.mAntisymmetryError <= tolerance)) {
        std::ostringstream message;
        message << "dense coefficients: C[k][i][j] = -C[j][i][k] fails by "
                << result.mAntisymmetryError << " (relative), above the tolerance " << tolerance
                << "; the array must be laid out as full[(k*N + i)*N + j]";
        throw Error(message.str());
    }
    return result;
}

double DenseCoefficients::entry(int k, int i, int j) const {
    if (k == j) return 0.0;
    if (k > j) return -entry(j, i, k);
    return mPacked[packedIndex(mN, k, i, j)];
}

std::vector<std::size_t> DenseCoefficients::threadBounds() const {
    const std::size_t n = std::size_t(mN);
    return splitRows(pairCount(n), contractionThreads(storedBytes()),
                     [n](std::size_t rows) { return rows * n; });
}

void DenseCoefficients::apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                              Eigen::VectorXd& out) const {
    checkSize("apply", a);
    checkSize("apply", b);
    out.setZero(mN);
    reduceOverRows(threadBounds(), out,
                   [&](std::size_t begin, std::size_t end, Eigen::VectorXd& acc) {
                       // s_p = Σ_i C[k][i][j] a_i for the range's pairs, as one GEMV over
                       // contiguous rows.
                       const Eigen::Map<const RowMajorMatrix> rows(mPacked.data() + begin * mN,
                                                                   Eigen::Index(end - begin), mN);
                       const Eigen::VectorXd s = rows * a;
                       for (std::size_t p = begin; p < end; ++p) {
                           const int k = mPairK[p], j = mPairJ[p];
                           acc[k] += s[p - begin] * b[j];
                           acc[j] -= s[p - begin] * b[k];  // C[j][i][k] = −C[k][i][j]
                       }
                   });
}

void DenseCoefficients::linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                  Eigen::MatrixXd& byI, Eigen::MatrixXd& byJ) const {
    checkSize("linearize", a);
    checkSize("linearize", b);
    byI.setZero(mN, mN);
    // byJ is accumulated transposed: row k of byJ gains Σ_j b_j C[k][·][j] and each row j > k
    // loses b_k C[k][·][j], i.e. contiguous columns. Rows are taken a chunk at a time: read once
    // from memory, then twice more from L1/L2 by three GEMV-like Eigen kernels.
    const std::size_t chunkRows = std::max<std::size_t>(1, kChunkBytes / (sizeof(double) * mN));
    Eigen::MatrixXd byJt = Eigen::MatrixXd::Zero(mN, mN);
    reduceOverRows(
        threadBounds(), byJt, [&](std::size_t begin, std::size_t end, Eigen::MatrixXd& acc) {
            Eigen::VectorXd s;
            for (std::size_t p = begin; p < end;) {
                const int k = mPairK[p], j = mPairJ[p];
                // Stay inside the block of pairs (k, ·), whose j are consecutive.
                const std::size_t m = std::min({end - p, chunkRows, std::size_t(mN - j)});
                const Eigen::Map<const RowMajorMatrix> rows(mPacked.data() + p * mN,
                                                            Eigen::Index(m), mN);
                s.noalias() = rows * a;
                byI.row(k).segment(j, Eigen::Index(m)) = s.transpose();  // owned by this pair range
                byI.col(k).segment(j, Eigen::Index(m)) = -s;
                acc.col(k).noalias() += rows.transpose() * b.segment(j, Eigen::Index(m));
                acc.middleCols(j, Eigen::Index(m)).noalias() -= b[k] * rows.transpose();
                p += m;
            }
        });
    byJ = byJt.transpose();
}

void DenseCoefficients::advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                               Eigen::VectorXd& out) const {
    checkSize("advect", u);
    checkSize("advect", x);
    out.setZero(mN);
    reduceOverRows(threadBounds(), out,
                   [&](std::size_t begin, std::size_t end, Eigen::VectorXd& acc) {
                       // out_m = Σ_{pairs k<j} C[k][m][j] (u_k x_j − u_j x_k): one transposed GEMV.
                       Eigen::VectorXd w(Eigen::Index(end - begin));
                       for (std::size_t p = begin; p < end; ++p) {
                           const int k = mPairK[p], j = mPairJ[p];
                           w[p - begin] = u[k] * x[j] - u[j] * x[k];
                       }
                       const Eigen::Map<const RowMajorMatrix> rows(mPacked.data() + begin * mN,
                                                                   Eigen::Index(end - begin), mN);
                       acc.noalias() += rows.transpose() * w;
                   });
}

}  // namespace modeflow
