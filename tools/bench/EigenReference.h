#pragma once
/// @file EigenReference.h
/// What the device's bandwidth-bound kernels are measured against: Eigen's float32 GEMVs on the
/// same data, one thread, and the counters that compare both. Eigen is timed two ways: paired,
/// one run right after each device round, so that both meet the same machine (on a shared VM the
/// load and the share of the L3 cache left to us vary 2× within minutes; Eigen's data is then
/// mostly out of the cache, as within a simulation step where other work runs between
/// contractions), and warm, its runs back to back after the rounds (its data in the cache where
/// it fits: the strict comparison for small data).

#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"

namespace modeflow::bench {

/// The median of `values` (0 for none).
double median(std::vector<double> values);

/// Sets counter `name` to the median of `values`.
void setMedian(benchmark::State& state, const std::string& name, const std::vector<double>& values);

/// One Eigen GEMV, timed: seconds of one call.
class EigenGemv {
public:
    virtual ~EigenGemv() = default;
    virtual double seconds() = 0;
};

/// The packed (pairs × N, row-major) dense coefficient matrix times a vector.
class PackedGemv final : public EigenGemv {
public:
    explicit PackedGemv(const DenseCoefficients& c);
    double seconds() override;

private:
    std::vector<float> mPacked;
    Eigen::Index mRows;
    Eigen::VectorXf mA, mSums;
};

/// The same rows of sparse coefficients in CSR (row-major sparse GEMV).
class SparseGemv final : public EigenGemv {
public:
    explicit SparseGemv(const SparseCoefficients& c);
    double seconds() override;

private:
    Eigen::SparseMatrix<float, Eigen::RowMajor> mMatrix;
    Eigen::VectorXf mA, mSums;
};

/// Ψv, or Ψᵀx when `transposed`, over a DOFs × N basis.
class BasisGemv final : public EigenGemv {
public:
    BasisGemv(const Eigen::MatrixXd& modes, bool transposed);
    double seconds() override;

private:
    Eigen::MatrixXf mBasis;
    bool mTransposed;
    Eigen::VectorXf mIn, mOut;
};

/// A device kernel's rounds against `gemv`: add() each round's device ms (one paired Eigen run
/// follows), then report() sets the counters over `bytes` (the float32 data both stream): the
/// median device round (`msName`), GB/s, Eigen_GB/s paired and warm, and the device's rate as a
/// share of Eigen's, paired and warm (%).
class DeviceAgainstEigen {
public:
    explicit DeviceAgainstEigen(EigenGemv& gemv) : mGemv(gemv) {}
    void add(double deviceMs);
    void report(benchmark::State& state, double bytes, const std::string& msName = "ms");

private:
    EigenGemv& mGemv;
    std::vector<double> mDeviceMs, mPairedMs;
};

}  // namespace modeflow::bench
