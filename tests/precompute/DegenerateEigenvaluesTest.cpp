// Lanczos from one start vector finds one vector per eigenspace (exactly so for a diagonal
// operator), so copies of a degenerate eigenvalue need the deflated runs of findMissedCopies:
// periodic axes make many (ShiftInvertEigensolver.h).

#include <gtest/gtest.h>

#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {
namespace {

/// 1, 2, 3 once, then `copies` times 4, then 5, 6, … once each.
Eigen::SparseMatrix<double> degenerate(int n, int copies) {
    Eigen::SparseMatrix<double> k(n, n);
    for (int i = 0; i < n; ++i)
        k.insert(i, i) = i < 3 ? i + 1.0 : i < 3 + copies ? 4.0 : double(i - copies + 5);
    return k;
}

TEST(DegenerateEigenvalues, DeflatedRunsFindEveryCopy) {
    const int n = 300, copies = 16, count = 30;
    const Eigen::VectorXd mass = Eigen::VectorXd::Constant(n, 2.0);
    EigenRequest request{count, -0.01, 1e-12, "test eigensolve", {}, false};
    const EigenPairs once = smallestEigenpairs(degenerate(n, copies), mass, request);
    int found = 0;
    for (Eigen::Index i = 0; i < once.values.size(); ++i)
        found += std::abs(2.0 * once.values[i] - 4.0) < 1e-9;
    EXPECT_LT(found, copies)
        << "one Lanczos run found every copy: this test no longer shows the need";

    request.findMissedCopies = true;
    const EigenPairs all = smallestEigenpairs(degenerate(n, copies), mass, request);
    ASSERT_EQ(all.values.size(), count);
    for (int i = 0; i < count; ++i) {
        const double exact = i < 3 ? i + 1.0 : i < 3 + copies ? 4.0 : double(i - copies + 5);
        EXPECT_NEAR(2.0 * all.values[i], exact, 1e-9) << "eigenvalue " << i + 1 << " (mass 2)";
    }
    const Eigen::MatrixXd gram = all.vectors.transpose() * mass.asDiagonal() * all.vectors;
    EXPECT_LE((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff(), 1e-10);
}

}  // namespace
}  // namespace modeflow
