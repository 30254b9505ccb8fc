#include "engine/dynamics/QuadratureSampling.h"

namespace modeflow {

void sampleRows(const SparseRows& m, std::int64_t first, const double* x, double* out,
                std::int64_t count) {
    for (std::int64_t r = 0; r < count; ++r) {
        double s = 0.0;
        for (std::int64_t t = m.start[first + r]; t < m.start[first + r + 1]; ++t)
            s += m.value[t] * x[m.column[t]];
        out[r] = s;
    }
}

Eigen::VectorXd sample(const SparseRows& m, const Eigen::Ref<const Eigen::VectorXd>& x) {
    Eigen::VectorXd out(m.rows());
    sampleRows(m, 0, x.data(), out.data(), m.rows());
    return out;
}

void addTransposed(const SparseRows& m, const Eigen::VectorXd& w, Eigen::VectorXd& g) {
    for (std::int64_t r = 0; r < m.rows(); ++r)
        for (std::int64_t t = m.start[r]; t < m.start[r + 1]; ++t)
            g[m.column[t]] += m.value[t] * w[r];
}

}  // namespace modeflow
