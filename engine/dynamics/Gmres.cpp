#include "engine/dynamics/Gmres.h"

#include <cmath>

namespace modeflow {

GmresResult gmres(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& product,
                  const Eigen::VectorXd& b, Eigen::VectorXd& x, double relativeTolerance,
                  int restart, int maxIterations) {
    GmresResult result;
    const Eigen::Index n = b.size();
    x.setZero(n);
    const double bNorm = b.norm();
    if (bNorm == 0.0) {
        result.converged = true;
        return result;
    }
    const double target = relativeTolerance * bNorm;
    Eigen::VectorXd r = b, w;
    Eigen::MatrixXd v(n, restart + 1);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(restart + 1, restart);
    Eigen::VectorXd cs(restart), sn(restart), g(restart + 1);
    while (result.iterations < maxIterations) {
        double beta = r.norm();
        if (beta <= target) break;
        v.col(0) = r / beta;
        g.setZero();
        g[0] = beta;
        int m = 0;
        for (; m < restart && result.iterations < maxIterations; ++m) {
            product(v.col(m), w);
            ++result.iterations;
            for (int i = 0; i <= m; ++i) {
                h(i, m) = v.col(i).dot(w);
                w -= h(i, m) * v.col(i);
            }
            const double next = w.norm();  // 0: the Krylov space holds the solution
            h(m + 1, m) = next;
            if (next > 0.0) v.col(m + 1) = w / next;
            for (int i = 0; i < m; ++i) {  // earlier rotations on the new column
                const double t = cs[i] * h(i, m) + sn[i] * h(i + 1, m);
                h(i + 1, m) = -sn[i] * h(i, m) + cs[i] * h(i + 1, m);
                h(i, m) = t;
            }
            const double d = std::hypot(h(m, m), h(m + 1, m));
            cs[m] = h(m, m) / d;
            sn[m] = h(m + 1, m) / d;
            h(m, m) = d;
            h(m + 1, m) = 0.0;
            g[m + 1] = -sn[m] * g[m];
            g[m] = cs[m] * g[m];
            if (std::abs(g[m + 1]) <= target || next == 0.0) {
                ++m;
                break;
            }
        }
        // x += V y with H y = g (upper triangular after the rotations).
        const Eigen::VectorXd y =
            h.topLeftCorner(m, m).triangularView<Eigen::Upper>().solve(g.head(m));
        x.noalias() += v.leftCols(m) * y;
        product(x, w);  // the true residual, free of the recurrence's round-off
        ++result.iterations;
        r = b - w;
    }
    result.residual = r.norm() / bNorm;
    result.converged = r.norm() <= target;
    return result;
}

}  // namespace modeflow
