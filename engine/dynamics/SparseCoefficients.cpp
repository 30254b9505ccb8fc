#include "engine/dynamics/SparseCoefficients.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/ParallelRows.h"

namespace modeflow {
namespace {

/// Frees a vector's memory (`v = {}` keeps its capacity: that assigns an empty initializer list).
template <typename T>
void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
}

/// Gives the allocator's free pages back to the system: the lists a cache was decoded into lie
/// in glibc's main heap, whose freed middle stays in the process until trimmed (the N = 10 000
/// box kept 5.5 GB of them for the whole run).
void returnFreedMemory() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

std::string describe(const CoefficientEntry& e) {
    return "C[" + std::to_string(e.k) + "][" + std::to_string(e.i) + "][" + std::to_string(e.j) +
           "]";
}

}  // namespace

SparseCoefficients::SparseCoefficients(int n, std::vector<CoefficientEntry> entries) {
    std::vector<std::int32_t> k(entries.size()), i(entries.size()), j(entries.size());
    std::vector<double> value(entries.size());
    for (std::size_t e = 0; e < entries.size(); ++e) {
        k[e] = entries[e].k;
        i[e] = entries[e].i;
        j[e] = entries[e].j;
        value[e] = entries[e].value;
    }
    release(entries);
    *this = fromLists(n, std::move(k), std::move(i), std::move(j), std::move(value));
}

SparseCoefficients SparseCoefficients::fromLists(int n, std::vector<std::int32_t> k,
                                                 std::vector<std::int32_t> i,
                                                 std::vector<std::int32_t> j,
                                                 std::vector<double> value) {
    if (n < 1)
        throw Error("sparse coefficients: the mode count must be positive, got " +
                    std::to_string(n));
    const std::size_t count = value.size();
    if (k.size() != count || i.size() != count || j.size() != count)
        throw Error("sparse coefficients: the lists of k, i, j and values have " +
                    std::to_string(k.size()) + ", " + std::to_string(i.size()) + ", " +
                    std::to_string(j.size()) + " and " + std::to_string(count) + " entries");
    for (std::size_t e = 0; e < count; ++e) {
        const CoefficientEntry entry{k[e], i[e], j[e], value[e]};
        if (entry.k < 0 || entry.j >= n || entry.i < 0 || entry.i >= n)
            throw Error("sparse coefficients: entry " + describe(entry) + " is outside " +
                        std::to_string(n) + " modes");
        if (entry.k >= entry.j)
            throw Error("sparse coefficients: entry " + describe(entry) +
                        " needs k < j (the k > j half is implied by antisymmetry and C[k][i][k] "
                        "= 0)");
    }
    // A counting sort of the non-zero entries into rows by pair (k, j), in the lists' order, then
    // by i within each row: the lists (20 bytes an entry) and the rows (12) are all that is held,
    // and the lists go as each array is filled, instead of a sort of 24-byte records beside both
    // (the N = 10 000 box: precompute/README.md "Closed-form bases").
    const auto nn = std::size_t(n);
    const auto pairOf = [&](std::size_t e) {
        return pairIndex(nn, std::size_t(k[e]), std::size_t(j[e]));
    };
    std::vector<std::uint32_t> rowOf(pairCount(nn), 0);  // entries of the pair, then its row + 1
    for (std::size_t e = 0; e < count; ++e)
        if (value[e] != 0.0) ++rowOf[pairOf(e)];
    SparseCoefficients c;
    c.mN = n;
    const auto rows = std::size_t(
        std::count_if(rowOf.begin(), rowOf.end(), [](std::uint32_t e) { return e > 0; }));
    c.mPairK.reserve(rows);
    c.mPairJ.reserve(rows);
    c.mRowStart.reserve(rows + 1);
    for (std::size_t p = 0, first = 0; first + 1 < nn; ++first)
        for (std::size_t second = first + 1; second < nn; ++second, ++p) {
            if (rowOf[p] == 0) continue;
            c.mPairK.push_back(int(first));
            c.mPairJ.push_back(int(second));
            c.mRowStart.push_back(c.mRowStart.back() + rowOf[p]);
            rowOf[p] = std::uint32_t(c.mPairK.size());
        }
    std::vector<std::uint32_t> filled(c.mPairK.size(), 0);
    const auto slotOf = [&](std::size_t e) {
        const std::size_t row = rowOf[pairOf(e)] - 1;
        return c.mRowStart[row] + filled[row]++;
    };
    // The values first (a dropped zero's i marked −1), so that their list's memory takes the
    // columns.
    c.mValue.resize(c.mRowStart.back());
    for (std::size_t e = 0; e < count; ++e) {
        if (value[e] != 0.0)
            c.mValue[slotOf(e)] = value[e];
        else
            i[e] = -1;
    }
    release(value);
    std::fill(filled.begin(), filled.end(), 0u);
    c.mColumn.resize(c.mRowStart.back());
    for (std::size_t e = 0; e < count; ++e)
        if (i[e] >= 0) c.mColumn[slotOf(e)] = i[e];
    release(i);
    release(k);
    release(j);
    release(rowOf);
    release(filled);
    returnFreedMemory();

    std::vector<std::pair<int, double>> row;
    for (std::size_t r = 0; r < c.mPairK.size(); ++r) {
        const std::size_t begin = c.mRowStart[r], end = c.mRowStart[r + 1];
        row.clear();
        for (std::size_t t = begin; t < end; ++t) row.emplace_back(c.mColumn[t], c.mValue[t]);
        std::sort(row.begin(), row.end(),
                  [](const auto& x, const auto& y) { return x.first < y.first; });
        for (std::size_t t = 0; t < row.size(); ++t) {
            if (t > 0 && row[t - 1].first == row[t].first)
                throw Error("sparse coefficients: entry " +
                            describe({c.mPairK[r], row[t].first, c.mPairJ[r], row[t].second}) +
                            " is given twice");
            c.mColumn[begin + t] = row[t].first;
            c.mValue[begin + t] = row[t].second;
        }
    }
    return c;
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
