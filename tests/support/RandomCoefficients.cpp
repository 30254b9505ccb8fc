#include "tests/support/RandomCoefficients.h"

#include <random>

#include "engine/core/PackedLayout.h"

namespace modeflow::testing {

std::vector<double> randomFullTensor(int n, std::uint64_t seed, double density) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::bernoulli_distribution keep(density);
    const auto at = [n](int k, int i, int j) { return (std::size_t(k) * n + i) * n + j; };
    std::vector<double> a(std::size_t(n) * n * n, 0.0), c(a.size(), 0.0);
    if (density >= 1.0) {
        for (double& x : a) x = value(rng);
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) c[at(k, i, j)] = a[at(k, i, j)] - a[at(j, i, k)];
        return c;
    }
    for (int k = 0; k < n; ++k)
        for (int j = k + 1; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (keep(rng)) {
                    c[at(k, i, j)] = value(rng);
                    c[at(j, i, k)] = -c[at(k, i, j)];
                }
    return c;
}

DenseCoefficients randomDense(int n, std::uint64_t seed, double density) {
    return DenseCoefficients::fromFull(n, randomFullTensor(n, seed, density));
}

DenseCoefficients randomPackedDense(int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::vector<double> packed(packedSize(std::size_t(n)));
    for (double& x : packed) x = value(rng);
    return DenseCoefficients(n, std::move(packed));
}

Eigen::VectorXd roundedToFloat(const Eigen::VectorXd& v) {
    return v.cast<float>().cast<double>();
}

DenseCoefficients roundedDense(const DenseCoefficients& c) {
    std::vector<double> packed(c.packed().size());
    for (std::size_t e = 0; e < packed.size(); ++e) packed[e] = double(float(c.packed()[e]));
    return DenseCoefficients(c.size(), std::move(packed));
}

Eigen::VectorXd randomVector(Eigen::Index n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    Eigen::VectorXd v(n);
    for (double& x : v) x = normal(rng);
    return v;
}

Eigen::VectorXd shapedKappaSquared(int n) {
    Eigen::VectorXd k2(n);
    for (int i = 0; i < n; ++i) k2[i] = (i % 2 == 0) ? 5.0 + 3.0 * i : 900.0 - 7.0 * i;
    return k2;
}

Eigen::VectorXd bruteApply(const StructuralCoefficients& c, const Eigen::VectorXd& a,
                           const Eigen::VectorXd& b) {
    const int n = c.size();
    Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) out[k] += c.entry(k, i, j) * a[i] * b[j];
    return out;
}

}  // namespace modeflow::testing
