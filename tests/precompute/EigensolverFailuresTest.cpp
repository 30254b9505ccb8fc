/// @file EigensolverFailuresTest.cpp
/// The shift-invert eigensolver fails with our message naming its stage, and CHOLMOD prints
/// nothing of its own (it used to print "CHOLMOD warning: ..." to stdout).

#include <gtest/gtest.h>

#include <string>

#include <Eigen/SparseCore>

#include "engine/core/Error.h"
#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {
namespace {

/// diag(first, 1, 2, …, n − 1): indefinite when first < shift.
Eigen::SparseMatrix<double> diagonal(int n, double first) {
    Eigen::SparseMatrix<double> k(n, n);
    for (int i = 0; i < n; ++i) k.insert(i, i) = i == 0 ? first : double(i);
    return k;
}

TEST(EigensolverFailures, AnIndefiniteOperatorIsRefusedQuietlyNamingTheStage) {
    const int n = 60;
    const EigenRequest request{4, -0.01, 1e-12, "test eigensolve", {}, false};
    std::string message;
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    try {
        smallestEigenpairs(diagonal(n, -5.0), Eigen::VectorXd::Ones(n), request);
    } catch (const Error& e) {
        message = e.what();
    }
    const std::string out = ::testing::internal::GetCapturedStdout();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(out + err, "") << "CHOLMOD printed";
    EXPECT_EQ(message.rfind("test eigensolve: the sparse Cholesky factorization failed", 0), 0u)
        << message;
    EXPECT_NE(message.find("not positive definite"), std::string::npos) << message;
}

TEST(EigensolverFailures, APositiveDefiniteOperatorStillSolves) {
    const int n = 60;
    const EigenPairs pairs = smallestEigenpairs(diagonal(n, 0.0), Eigen::VectorXd::Ones(n),
                                                {4, -0.01, 1e-12, "test eigensolve", {}, false});
    ASSERT_EQ(pairs.values.size(), 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(pairs.values[i], double(i), 1e-10) << i;
}

}  // namespace
}  // namespace modeflow
