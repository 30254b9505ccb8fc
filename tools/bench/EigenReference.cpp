#include "tools/bench/EigenReference.h"

#include <algorithm>
#include <chrono>

namespace modeflow::bench {
namespace {

template <typename Work>
double secondsOf(Work work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

void setMedian(benchmark::State& state, const std::string& name,
               const std::vector<double>& values) {
    state.counters[name] = median(values);
}

PackedGemv::PackedGemv(const DenseCoefficients& c)
    : mPacked(c.packed().begin(), c.packed().end()),
      mRows(Eigen::Index(c.packed().size()) / c.size()),
      mA(Eigen::VectorXf::Random(c.size())),
      mSums(mRows) {}

double PackedGemv::seconds() {
    const Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
        matrix(mPacked.data(), mRows, mA.size());
    const double s = secondsOf([&] { mSums.noalias() = matrix * mA; });
    benchmark::DoNotOptimize(mSums.data());
    return s;
}

SparseGemv::SparseGemv(const SparseCoefficients& c)
    : mMatrix(Eigen::Index(c.pairK().size()), c.size()), mA(Eigen::VectorXf::Random(c.size())) {
    std::vector<Eigen::Triplet<float>> entries;
    for (std::size_t r = 0; r < c.pairK().size(); ++r)
        for (std::size_t e = std::size_t(c.rowStart()[r]); e < std::size_t(c.rowStart()[r + 1]);
             ++e)
            entries.emplace_back(int(r), int(c.columns()[e]), float(c.values()[e]));
    mMatrix.setFromTriplets(entries.begin(), entries.end());
    mSums.resize(mMatrix.rows());
}

double SparseGemv::seconds() {
    const double s = secondsOf([&] { mSums.noalias() = mMatrix * mA; });
    benchmark::DoNotOptimize(mSums.data());
    return s;
}

BasisGemv::BasisGemv(const Eigen::MatrixXd& modes, bool transposed)
    : mBasis(modes.cast<float>()),
      mTransposed(transposed),
      mIn(Eigen::VectorXf::Random(transposed ? modes.rows() : modes.cols())),
      mOut(transposed ? modes.cols() : modes.rows()) {}

double BasisGemv::seconds() {
    const double s = secondsOf([&] {
        if (mTransposed)
            mOut.noalias() = mBasis.transpose() * mIn;
        else
            mOut.noalias() = mBasis * mIn;
    });
    benchmark::DoNotOptimize(mOut.data());
    return s;
}

void DeviceAgainstEigen::add(double deviceMs) {
    mDeviceMs.push_back(deviceMs);
    mPairedMs.push_back(1e3 * mGemv.seconds());
}

void DeviceAgainstEigen::report(benchmark::State& state, double bytes, const std::string& msName) {
    std::vector<double> warmMs;
    for (std::size_t r = 0; r < mDeviceMs.size(); ++r) warmMs.push_back(1e3 * mGemv.seconds());
    const double device = median(mDeviceMs), paired = median(mPairedMs), warm = median(warmMs);
    state.counters[msName] = device;
    state.counters["GB/s"] = bytes / device * 1e-6;
    state.counters["Eigen_GB/s_paired"] = bytes / paired * 1e-6;
    state.counters["Eigen_GB/s_warm"] = bytes / warm * 1e-6;
    state.counters["share%_paired"] = 100.0 * paired / device;
    state.counters["share%_warm"] = 100.0 * warm / device;
}

}  // namespace modeflow::bench
