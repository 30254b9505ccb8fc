#pragma once
/// @file SeparableTransform.h
/// The transforms of a closed-form velocity basis on the device (CPU reference:
/// engine/basis/SeparableTransform.h), so that a device run never forms the basis's columns:
/// reconstruction v → face field and projection q → f = Ψᵀ(w ∘ q) as separable per-axis sums over
/// the band of wave numbers in use (shaders/separable_pass.comp: one dispatch per axis and
/// component, each output a dot product with a row of the axis's table of factors), the modes
/// gathered into and out of each component's tensor of slots (separable_gather.comp); a
/// reconstruction's last pass writes each component's velocities straight into its faces (the
/// DOFs are the box's non-wall faces in grid order, SeparableTransform checks, so that is a
/// strided write, far cheaper on lavapipe than the scatter through the DOF faces it replaced:
/// precompute/README.md "Closed-form bases"). float32; the tables are computed in double on the
/// host.

#include <array>
#include <cstdint>

#include "engine/format/BasisCache.h"
#include "engine/simulation/ProjectionWeights.h"
#include "engine/simulation/SmokeDisplacement.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SeparableTransformKernels {
public:
    /// For the closed-form basis of `cache` on its DOFs.
    /// @throw modeflow::Error for a basis that is not closed form or not on the whole box's faces
    ///        (SeparableTransform), projection weights that differ along one normal axis, or a
    ///        device error.
    SeparableTransformKernels(const vulkan::VulkanContext& context, const BasisCache& cache);

    /// Records faceField = the face field of Σ v_i Ψ_i (v: N floats at least; faces that are not
    /// DOFs are not written). With `needed`, at least the faces on the sides of its cells
    /// (recordFaceFieldProjection's box): the passes take only the lines those need, and other
    /// faces may keep what they held.
    void recordReconstruction(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& v,
                              const vulkan::DeviceBuffer& faceField,
                              const CellBox* needed = nullptr) const;
    /// Records f = Ψᵀ (w ∘ q): q one force density per DOF (DOF order), w = projectionWeights
    /// for FaceQuantity::Density.
    void recordProjection(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& q,
                          const vulkan::DeviceBuffer& f) const;
    /// The same for a q that is 0 on every DOF but those of component `component` (buoyancy
    /// without splats: the up faces alone), whose passes alone are recorded: a third of a 3D
    /// projection's.
    /// @throw modeflow::Error for a component outside the grid's dimensions.
    void recordComponentProjection(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& q,
                                   int component, const vulkan::DeviceBuffer& f) const;
    /// The same for q a face field's values at the DOFs (DOF order), w for
    /// FaceQuantity::FaceField: the exact inverse of the reconstruction.
    /// With `nonZero`, q is 0 on every face but those on the sides of its cells (first may lie
    /// off the grid along periodic axes, where the box wraps), and the passes take only the
    /// lines and inputs of that box (an obstacle's mismatch: a box around the solid).
    void recordFaceFieldProjection(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& q,
                                   const vulkan::DeviceBuffer& f,
                                   const CellBox* nonZero = nullptr) const;

    std::uint32_t modeCount() const { return mModeCount; }
    std::uint32_t dofCount() const { return mDofCount; }

private:
    /// One axis pass's shape and table.
    struct Pass {
        std::uint32_t d1, d2, inLength, outLength, tableTexel;
    };
    /// Where the last pass of a component's passes writes: its first value, rows and planes.
    struct Placement {
        std::uint32_t offset = 0, row = 0, plane = 0;  ///< row, plane 0: packed
    };
    /// DOF positions [first, first + count) along one axis.
    struct Range {
        std::uint32_t first = 0, count = 0;
    };
    /// Records the three passes of component `normal` (synthesis or analysis); `window`: the DOF
    /// positions per axis outside which an analysis's input is 0, or a synthesis's output is not
    /// needed.
    void recordPasses(vulkan::CommandSequence& sequence, int normal, bool synthesis,
                      const vulkan::DeviceBuffer& in, std::uint32_t inOffset,
                      const vulkan::DeviceBuffer& out, Placement placement,
                      const std::array<Range, 3>* window = nullptr) const;
    /// f from the DOF values in `q` (mGatherWeights[quantity]); `component` ≥ 0: that
    /// component's DOFs alone, the others' slots zeroed; `nonZero` as recordFaceFieldProjection.
    void recordAnalysis(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& q,
                        FaceQuantity quantity, const vulkan::DeviceBuffer& f, int component = -1,
                        const CellBox* nonZero = nullptr) const;
    /// The DOF positions of component `normal` on the sides of `cells` (all of an axis the box
    /// wraps along).
    std::array<Range, 3> dofWindow(int normal, const CellBox& cells) const;

    const vulkan::VulkanContext& mContext;
    int mDim = 3;
    std::uint32_t mModeCount = 0, mDofCount = 0, mSlotCount = 0, mFaceTotal = 0;
    std::array<std::uint32_t, 3> mDofStart{0, 0, 0};
    std::array<std::array<std::uint32_t, 3>, 3> mPositions{};  ///< [normal][axis] DOF positions
    std::array<int, 3> mCells{1, 1, 1};
    std::array<bool, 3> mPeriodic{false, false, false};
    std::array<Placement, 3> mFacePlacement{};  ///< each component's faces in the face field
    std::array<std::array<Pass, 3>, 3> mSynthesis{}, mAnalysis{};  ///< [normal][axis]
    vulkan::DeviceBuffer mTables;
    vulkan::DeviceBuffer mScatterIndex, mScatterWeight;  ///< modes → slots: 2 terms a slot
    vulkan::DeviceBuffer mGatherIndex;                   ///< slots → modes: a term per component
    std::array<vulkan::DeviceBuffer, 2> mGatherWeights;  ///< by FaceQuantity
    vulkan::DeviceBuffer mSlots;                         ///< the components' tensors of slots
    vulkan::DeviceBuffer mScratchA, mScratchB;           ///< between passes
    vulkan::ComputeKernel mPassKernel, mGatherKernel;
};

}  // namespace modeflow::device
