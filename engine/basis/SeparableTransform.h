#pragma once
/// @file SeparableTransform.h
/// Ψ v and Ψᵀ q of a closed-form velocity basis (engine/format/SeparableModes.h) without its
/// columns: each component of the field is a sum of products of one trigonometric factor per
/// axis, so it is a tensor of coefficients over the band of wave numbers in use (the slots of an
/// axis: l on a wall axis, (l, phase) on a periodic one) taken to the grid by a 1-D transform
/// along each axis in turn, and back by the transposed transforms:
///
///   wall axis     cosines at cell centres   DCT-III (FFTW REDFT01), transposed DCT-II (REDFT10)
///                 sines at interior faces   DST-I (RODFT00), its own transpose
///   periodic axis cosines at cell centres,  a real inverse DFT (HC2R) of the slots as complex
///                 sines at every face       amplitudes with the phase and the half-cell shift as
///                                           twiddles; transposed by the forward DFT (R2HC)
///
/// zero-padded from the band to the axis. A pass along one axis transforms only the lines that
/// hold data (band × band lines on the first pass, grid × band on the second, grid × grid on the
/// last), so a 64³ box at N = 1000 (a band of 11 per axis) costs about 5000 FFTs of length 64 per
/// component, against 786 000 × 1000 multiply-adds for the dense columns.
///
/// The DOF order is the whole box's (precompute/closedform/WholeBoxDofs: faces by normal axis,
/// x fastest, interior faces only on wall axes), checked against the cache. The FFT buffers are
/// the object's own: one call at a time.

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"

namespace modeflow {

class SeparableTransform {
public:
    /// For the velocity descriptors of `cache` (a closed-form basis) on its face DOFs.
    /// @throw modeflow::Error when the basis is not closed form or its DOFs are not the whole
    ///        box's.
    explicit SeparableTransform(const BasisCache& cache);
    ~SeparableTransform();
    SeparableTransform(const SeparableTransform&) = delete;
    SeparableTransform& operator=(const SeparableTransform&) = delete;

    int modeCount() const { return int(mModes.size()); }
    std::int64_t dofCount() const { return mDofCount; }

    /// Ψ v: the flux of Σ v_i Ψ_i through every DOF face (cache.faces order).
    Eigen::VectorXd fluxes(const Eigen::VectorXd& v) const;
    /// Ψᵀ q for q given per DOF.
    Eigen::VectorXd transposed(const Eigen::VectorXd& q) const;

    /// Slots of `axis`: band + 1 wave numbers on a wall axis, 2 (band + 1) on a periodic one (slot
    /// 2l + phase); 1 on an axis the grid does not have.
    int slotCount(int axis) const { return mSlots[std::size_t(axis)]; }
    /// The slot of `mode` along `axis`.
    int slotOf(const SeparableMode& mode, int axis) const;
    /// Positions of component `normal` along `axis`: interior faces (n − 1) on a wall normal axis,
    /// n on a periodic one, n cells across; 1 on an axis the grid does not have.
    int positionCount(int normal, int axis) const;
    /// The 1-D factor table of component `normal` along `axis`: positions × slots, row-major,
    /// entry (p, k) = the factor of slot k at position p (the sine at a face on the normal axis,
    /// the cosine at a cell centre across it). What the device's per-axis sums multiply with.
    std::vector<double> factorTable(int normal, int axis) const;

private:
    struct Pass;
    /// The mode's place in a component's tensor of slots (x fastest).
    std::size_t tensorSlot(const SeparableMode& mode) const;
    /// One component's tensor through its three passes (synthesis: slots → positions).
    void synthesize(int normal, std::vector<double>& tensor) const;
    /// The transposed passes (positions → slots).
    void analyze(int normal, std::vector<double>& tensor) const;

    GridSpec mGrid;
    std::vector<SeparableMode> mModes;
    std::int64_t mDofCount = 0;
    std::array<int, 3> mSlots{1, 1, 1};
    std::array<std::int64_t, 3> mDofStart{0, 0, 0};  ///< first DOF of each component
    std::array<double, 3> mArea{1.0, 1.0, 1.0};
    /// Passes by [normal][axis]: synthesis and analysis.
    std::array<std::array<std::unique_ptr<Pass>, 3>, 3> mSynthesis, mAnalysis;
};

}  // namespace modeflow
