#include "engine/dynamics/SparseCoefficients.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/ParallelRows.h"

namespace modeflow {
namespace {

std::string describe(const CoefficientEntry& e) {
    return "C[" + std::to_string(e.k) + "][" + std::to_string(e.i) + "][" + std::to_string(e.j) +
           "]";
}

}  // namespace

SparseCoefficients::SparseCoefficients(int n, std::vector<CoefficientEntry> entries) : mN(n) {
    if (n < 1)
        throw Error("sparse coefficients: the mode count must be positive, got " +
                    std::to_string(n));
    for (const CoefficientEntry& e : entries) {
        if (e.k < 0 || e.j >= n || e.i < 0 || e.i >= n) {
            throw Error("sparse coefficients: entry " + describe(e) + " is outside " +
                        std::to_string(n) + " modes");
        }
        if (e.k >= e.j) {
            throw Error("sparse coefficients: entry " + describe(e) + " needs k < j (the k > j " +
                        "half is implied by antisymmetry and C[k][i][k] = 0)");
        }
    }
    const auto key = [](const CoefficientEntry& e) { return std::tie(e.k, e.j, e.i); };
    const auto before = [&](const CoefficientEntry& x, const CoefficientEntry& y) {
        return key(x) < key(y);
    };
    std::sort(entries.begin(), entries.end(), before);
    for (std::size_t t = 0; t < entries.size(); ++t) {
        const CoefficientEntry& e = entries[t];
        if (t > 0 && key(entries[t - 1]) == key(e)) {
            throw Error("sparse coefficients: entry " + describe(e) + " is given twice");
        }
        if (e.value == 0.0) continue;
        if (mPairK.empty() || mPairK.back() != e.k || mPairJ.back() != e.j) {
            mPairK.push_back(e.k);
            mPairJ.push_back(e.j);
            mRowStart.push_back(mRowStart.back());
        }
        mColumn.push_back(e.i);
        mValue.push_back(e.value);
        ++mRowStart.back();
    }
}

SparseCoefficients SparseCoefficients::fromDense(const DenseCoefficients& dense,
                                                 double relativeDropTolerance) {
    const std::vector<double>& packed = dense.packed();
    double largest = 0.0;
    for (double c : packed) largest = std::max(largest, std::abs(c));
    const double threshold = relativeDropTolerance * largest;
    const int n = dense.size();
    std::vector<CoefficientEntry> entries;
    for (int k = 0; k < n; ++k) {
        for (int j = k + 1; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const double c = packed[packedIndex(n, k, i, j)];
                if (c != 0.0 && std::abs(c) > threshold) entries.push_back({k, i, j, c});
            }
        }
    }
    return SparseCoefficients(n, std::move(entries));
}

double SparseCoefficients::density() const {
    return double(nonZeros()) / double(packedSize(std::size_t(mN)));
}

std::size_t SparseCoefficients::storedBytes() const {
    return mValue.size() * (sizeof(double) + sizeof(int)) +
           mPairK.size() * (2 * sizeof(int) + sizeof(std::size_t));
}

double SparseCoefficients::entry(int k, int i, int j) const {
    if (k == j) return 0.0;
    if (k > j) return -entry(j, i, k);
    std::size_t lo = 0, hi = mPairK.size();
    while (lo < hi) {  // first row whose pair is not before (k, j)
        const std::size_t mid = (lo + hi) / 2;
        if (std::tie(mPairK[mid], mPairJ[mid]) < std::tie(k, j))
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == mPairK.size() || mPairK[lo] != k || mPairJ[lo] != j) return 0.0;
    const auto first = mColumn.begin() + std::ptrdiff_t(mRowStart[lo]);
    const auto last = mColumn.begin() + std::ptrdiff_t(mRowStart[lo + 1]);
    const auto at = std::lower_bound(first, last, i);
    return at != last && *at == i ? mValue[std::size_t(at - mColumn.begin())] : 0.0;
}

std::vector<std::size_t> SparseCoefficients::threadBounds() const {
    return splitRows(mPairK.size(), contractionThreads(storedBytes()),
                     [this](std::size_t rows) { return mRowStart[rows] + 2 * rows; });
}

double SparseCoefficients::rowDot(std::size_t r, const Eigen::VectorXd& a) const {
    double s = 0.0;
    for (std::size_t t = mRowStart[r]; t < mRowStart[r + 1]; ++t) s += mValue[t] * a[mColumn[t]];
    return s;
}

void SparseCoefficients::apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                               Eigen::VectorXd& out) const {
    checkSize("apply", a);
    checkSize("apply", b);
    out.setZero(mN);
    reduceOverRows(threadBounds(), out,
                   [&](std::size_t begin, std::size_t end, Eigen::VectorXd& acc) {
                       for (std::size_t r = begin; r < end; ++r) {
                           const double s = rowDot(r, a);
                           acc[mPairK[r]] += s * b[mPairJ[r]];
                           acc[mPairJ[r]] -= s * b[mPairK[r]];  // C[j][i][k] = −C[k][i][j]
                       }
                   });
}

void SparseCoefficients::linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                   Eigen::MatrixXd& byI, Eigen::MatrixXd& byJ) const {
    checkSize("linearize", a);
    checkSize("linearize", b);
    byI.setZero(mN, mN);
    // Accumulated transposed, as in the dense storage: each pair touches two columns.
    Eigen::MatrixXd byJt = Eigen::MatrixXd::Zero(mN, mN);
    reduceOverRows(
        threadBounds(), byJt, [&](std::size_t begin, std::size_t end, Eigen::MatrixXd& acc) {
            for (std::size_t r = begin; r < end; ++r) {
                const int k = mPairK[r], j = mPairJ[r];
                const double s = rowDot(r, a);
                byI(k, j) = s;  // each row owns these two entries, so threads never collide
                byI(j, k) = -s;
                for (std::size_t t = mRowStart[r]; t < mRowStart[r + 1]; ++t) {
                    acc(mColumn[t], k) += b[j] * mValue[t];
                    acc(mColumn[t], j) -= b[k] * mValue[t];
                }
            }
        });
    byJ = byJt.transpose();
}

void SparseCoefficients::advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                                Eigen::VectorXd& out) const {
    checkSize("advect", u);
    checkSize("advect", x);
    out.setZero(mN);
    reduceOverRows(
        threadBounds(), out, [&](std::size_t begin, std::size_t end, Eigen::VectorXd& acc) {
            for (std::size_t r = begin; r < end; ++r) {
                const int k = mPairK[r], j = mPairJ[r];
                const double w = u[k] * x[j] - u[j] * x[k];  // see DenseCoefficients::advect
                for (std::size_t t = mRowStart[r]; t < mRowStart[r + 1]; ++t) {
                    acc[mColumn[t]] += w * mValue[t];
                }
            }
        });
}

}  // namespace modeflow
