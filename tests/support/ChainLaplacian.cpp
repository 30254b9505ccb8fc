#include "tests/support/ChainLaplacian.h"

#include <vector>

namespace modeflow::testing {

Eigen::SparseMatrix<double> chainLaplacian(int n) {
    const double h = 1.0 / (n + 1);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, 2.0 / h);
        if (i + 1 < n) {
            t.emplace_back(i, i + 1, -1.0 / h);
            t.emplace_back(i + 1, i, -1.0 / h);
        }
    }
    Eigen::SparseMatrix<double> k(n, n);
    k.setFromTriplets(t.begin(), t.end());
    return k;
}

}  // namespace modeflow::testing
