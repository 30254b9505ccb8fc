#include "engine/device/SeparableTransform.h"

#include <algorithm>
#include <string>
#include <vector>

#include "engine/basis/SeparableTransform.h"
#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/device/DofFaces.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SeparableParams.h"
#include "shaders/separable_gather.spv.h"
#include "shaders/separable_pass.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroup = 64;

template <typename T>
vulkan::DeviceBuffer upload(const vulkan::VulkanContext& context, const std::vector<T>& values,
                            const char* name) {
    return vulkan::DeviceBuffer::fromValues<T>(context, values, name);
}

/// The weight each component's DOFs get in a projection: one per normal axis on a whole box.
std::array<double, 3> componentWeights(const BasisCache& cache, FaceQuantity quantity,
                                       const std::array<std::uint32_t, 3>& start,
                                       std::uint32_t dofs) {
    const Eigen::VectorXd w = projectionWeights(cache, quantity);
    std::array<double, 3> out{0.0, 0.0, 0.0};
    for (int a = 0; a < cache.grid.dim; ++a) {
        const std::uint32_t end = a + 1 < cache.grid.dim ? start[std::size_t(a + 1)] : dofs;
        out[std::size_t(a)] = w[start[std::size_t(a)]];
        for (std::uint32_t d = start[std::size_t(a)]; d < end; ++d)
            if (w[d] != out[std::size_t(a)])
                throw Error("separable transform: projection weights differ along normal axis " +
                            std::to_string(a));
    }
    return out;
}

}  // namespace

SeparableTransformKernels::SeparableTransformKernels(const vulkan::VulkanContext& context,
                                                     const BasisCache& cache)
    : mContext(context),
      mTables(context, 4),
      mScatterIndex(context, 4),
      mScatterWeight(context, 4),
      mGatherIndex(context, 4),
      mGatherWeights{vulkan::DeviceBuffer(context, 4), vulkan::DeviceBuffer(context, 4)},
      mSlots(context, 4),
      mScratchA(context, 4),
      mScratchB(context, 4),
      mPassKernel(context, {"separable_pass",
                            separable_pass_spv,
                            3,
                            sizeof(shaders::SeparablePassParams),
                            kWorkgroup,
                            {},
                            {0},
                            {},
                            {1}}),
      mGatherKernel(context, {"separable_gather", separable_gather_spv, 4,
                              sizeof(shaders::SeparableGatherParams), kWorkgroup}) {
    const SeparableTransform host(cache);  // the checks, slots and tables
    mDim = cache.grid.dim;
    mModeCount = std::uint32_t(host.modeCount());
    mDofCount = std::uint32_t(host.dofCount());
    mFaceTotal = std::uint32_t(MacGrid::fromSpec(cache.grid).faceTotal());
    const std::array<std::uint32_t, 3> k{std::uint32_t(host.slotCount(0)),
                                         std::uint32_t(host.slotCount(1)),
                                         std::uint32_t(host.slotCount(2))};
    mSlotCount = k[0] * k[1] * k[2];

    // The tables, each pass's shape (as the CPU's passes: synthesis x, y, z from slots to
    // positions, analysis x, y, z back), and the scratch the passes need.
    std::vector<float> tables;
    std::uint64_t scratch = 1, start = 0;
    for (int normal = 0; normal < mDim; ++normal) {
        mDofStart[std::size_t(normal)] = std::uint32_t(start);
        std::array<std::uint32_t, 3> p{};
        for (int a = 0; a < 3; ++a)
            p[std::size_t(a)] = std::uint32_t(host.positionCount(normal, a));
        start += std::uint64_t(p[0]) * p[1] * p[2];
        mPositions[std::size_t(normal)] = p;
        for (int axis = 0; axis < 3; ++axis) {
            const std::vector<double> table = host.factorTable(normal, axis);  // P × K
            const std::uint32_t rows = p[std::size_t(axis)], cols = k[std::size_t(axis)];
            // Input-major, outputs in blocks of four a texel (separable_pass.comp): synthesis
            // (positions from slots) the table's columns, analysis (slots from positions) its rows.
            const auto store = [&](std::uint32_t outputs, std::uint32_t inputs, bool transposed) {
                const std::uint32_t blocks = (outputs + 3) / 4;
                const auto texel = std::uint32_t(tables.size() / 4);
                tables.resize(tables.size() + std::size_t(inputs) * blocks * 4, 0.0f);
                for (std::uint32_t j = 0; j < inputs; ++j)
                    for (std::uint32_t q = 0; q < outputs; ++q)
                        tables[(std::size_t(texel) + std::size_t(j) * blocks) * 4 + q] =
                            float(transposed ? table[std::size_t(q) * cols + j]
                                             : table[std::size_t(j) * cols + q]);
                return texel;
            };
            const std::uint32_t synthesisOffset = store(rows, cols, true);
            const std::uint32_t analysisOffset = store(cols, rows, false);
            // Before pass `axis`, the axes before it are done (positions, or slots in analysis).
            std::array<std::uint32_t, 3> before = k, after = p;
            if (axis >= 1) before[0] = p[0], after[0] = k[0];
            if (axis >= 2) before[1] = p[1], after[1] = k[1];
            const std::uint32_t s1 = (axis + 1) % 3, s2 = (axis + 2) % 3;
            // The two other axes in rotated order: (axis+1, axis+2) → (d1, d2).
            mSynthesis[std::size_t(normal)][std::size_t(axis)] = {before[s1], before[s2], cols,
                                                                  rows, synthesisOffset};
            mAnalysis[std::size_t(normal)][std::size_t(axis)] = {after[s1], after[s2], rows, cols,
                                                                 analysisOffset};
            scratch =
                std::max<std::uint64_t>(scratch, std::uint64_t(before[s1]) * before[s2] * rows);
            scratch = std::max<std::uint64_t>(scratch, std::uint64_t(after[s1]) * after[s2] * cols);
        }
    }
    mTables = upload(context, tables, "separable tables");
    mScratchA = vulkan::DeviceBuffer(context, scratch * sizeof(float), "separable scratch A");
    mScratchB = vulkan::DeviceBuffer(context, scratch * sizeof(float), "separable scratch B");
    mSlots = vulkan::DeviceBuffer(context, std::uint64_t(mDim) * mSlotCount * sizeof(float),
                                  "separable slots");

    // Modes ↔ slots: a slot holds at most two modes of one component (the two polarizations of
    // a 3D wave vector; on periodic axes the phases are slots of their own).
    const std::size_t slots = std::size_t(mDim) * mSlotCount;
    std::vector<std::uint32_t> scatterIndex(2 * slots, SEPARABLE_NONE),
        gatherIndex(std::size_t(mDim) * mModeCount);
    std::vector<float> scatterWeight(2 * slots, 0.0f);
    std::array<std::vector<float>, 2> gatherWeights{std::vector<float>(gatherIndex.size()),
                                                    std::vector<float>(gatherIndex.size())};
    const MacGrid mac = MacGrid::fromSpec(cache.grid);
    mCells = mac.cells;
    mPeriodic = mac.periodic;
    // Component a's DOFs are its faces off the walls in grid order (SeparableTransform checked:
    // wholeBoxFaces), x fastest as the last synthesis pass leaves them: position (x, y, z) is
    // face (x, y, z) + 1 along a walled normal axis.
    for (int a = 0; a < mDim; ++a) {
        const std::array<int, 3> e = mac.faceExtent(a);
        const int wall = cache.grid.isPeriodic(a) ? 0 : 1;
        mFacePlacement[std::size_t(a)] = {
            std::uint32_t(
                mac.faceIndex(a, a == 0 ? wall : 0, a == 1 ? wall : 0, a == 2 ? wall : 0)),
            std::uint32_t(e[0]), std::uint32_t(e[0] * e[1])};
    }
    const std::array<FaceQuantity, 2> quantities{FaceQuantity::Density, FaceQuantity::FaceField};
    std::array<std::array<double, 3>, 2> weights{};
    for (int q = 0; q < 2; ++q)
        weights[std::size_t(q)] =
            componentWeights(cache, quantities[std::size_t(q)], mDofStart, mDofCount);
    for (std::uint32_t m = 0; m < mModeCount; ++m) {
        const SeparableMode& mode = cache.velocity.separable[m];
        const std::size_t slot =
            (std::size_t(host.slotOf(mode, 2)) * k[1] + std::size_t(host.slotOf(mode, 1))) * k[0] +
            std::size_t(host.slotOf(mode, 0));
        for (int a = 0; a < mDim; ++a) {
            const double amplitude = mode.amplitude[std::size_t(a)];
            const std::size_t term = std::size_t(a) * mModeCount + m;
            gatherIndex[term] = amplitude == 0.0
                                    ? SEPARABLE_NONE
                                    : std::uint32_t(std::size_t(a) * mSlotCount + slot);
            for (int q = 0; q < 2; ++q)
                gatherWeights[std::size_t(q)][term] =
                    float(amplitude * mac.faceArea(a) * weights[std::size_t(q)][std::size_t(a)]);
            if (amplitude == 0.0) continue;
            const std::size_t at = 2 * (std::size_t(a) * mSlotCount + slot);
            const std::size_t t = scatterIndex[at] == SEPARABLE_NONE ? at : at + 1;
            if (scatterIndex[t] != SEPARABLE_NONE)
                throw Error("separable transform: more than two modes share a wave vector slot");
            scatterIndex[t] = m;
            scatterWeight[t] = float(amplitude);
        }
    }
    // The gather reads a term per component for each mode: terms are component-major above,
    // transposed here to mode-major (index[e terms + t]).
    std::vector<std::uint32_t> byMode(gatherIndex.size());
    std::array<std::vector<float>, 2> weightsByMode{std::vector<float>(byMode.size()),
                                                    std::vector<float>(byMode.size())};
    for (std::uint32_t m = 0; m < mModeCount; ++m)
        for (int a = 0; a < mDim; ++a) {
            const std::size_t from = std::size_t(a) * mModeCount + m,
                              to = std::size_t(m) * std::size_t(mDim) + std::size_t(a);
            byMode[to] = gatherIndex[from];
            for (int q = 0; q < 2; ++q)
                weightsByMode[std::size_t(q)][to] = gatherWeights[std::size_t(q)][from];
        }
    mScatterIndex = upload(context, scatterIndex, "separable scatter index");
    mScatterWeight = upload(context, scatterWeight, "separable scatter weight");
    mGatherIndex = upload(context, byMode, "separable gather index");
    for (int q = 0; q < 2; ++q)
        mGatherWeights[std::size_t(q)] =
            upload(context, weightsByMode[std::size_t(q)], "separable gather weight");
}

void SeparableTransformKernels::recordPasses(vulkan::CommandSequence& sequence, int normal,
                                             bool synthesis, const vulkan::DeviceBuffer& in,
                                             std::uint32_t inOffset,
                                             const vulkan::DeviceBuffer& out, Placement placement,
                                             const std::array<Range, 3>* window) const {
    const std::array<const vulkan::DeviceBuffer*, 4> chain{&in, &mScratchA, &mScratchB, &out};
    for (int axis = 0; axis < 3; ++axis) {
        const Pass& pass =
            (synthesis ? mSynthesis : mAnalysis)[std::size_t(normal)][std::size_t(axis)];
        shaders::SeparablePassParams params{};
        params.d1 = pass.d1;
        params.d2 = pass.d2;
        params.inLength = pass.inLength;
        params.outLength = pass.outLength;
        params.inOffset = axis == 0 ? inOffset : 0;
        const bool last = axis == 2;
        params.outOffset = last ? placement.offset : 0;
        params.tableTexel = pass.tableTexel;
        params.outRow = last && placement.row != 0 ? placement.row : pass.d1;
        params.outPlane = last && placement.plane != 0 ? placement.plane : pass.d1 * pass.d2;
        Range i1{0, pass.d1}, i2{0, pass.d2}, j{0, pass.inLength}, q{0, pass.outLength};
        if (window && !synthesis) {
            // Analysis lines run along x, then y, then z, the other axes rotated into (d1, d2):
            // (y, z) positions, then (z, x slots), then (x slots, y slots). Each pass reads only
            // the lines the one before wrote: the window's positions.
            const auto& w = *window;
            j = w[std::size_t(axis)];
            if (axis == 0) i1 = w[1], i2 = w[2];
            if (axis == 1) i1 = w[2];
        } else if (window) {
            // Synthesis lines run along x, then y, then z: (y, z slots), then (z slots, x
            // positions), then (x, y positions); each pass writes the window's positions along
            // its axis, the next one reads only those.
            const auto& w = *window;
            q = w[std::size_t(axis)];
            if (axis == 1) i2 = w[0];
            if (axis == 2) i1 = w[0], i2 = w[1];
        }
        params.i1First = i1.first;
        params.i1Count = i1.count;
        params.i2First = i2.first;
        params.i2Count = i2.count;
        params.jFirst = j.first;
        params.jCount = j.count;
        params.outFirst = q.first;
        params.outCount = q.count;
        const std::array<const vulkan::DeviceBuffer*, 3> buffers{&mTables, chain[std::size_t(axis)],
                                                                 chain[std::size_t(axis) + 1]};
        const std::uint64_t outputsPerInvocation = 4 * SEPARABLE_BLOCKS_PER_INVOCATION;
        const std::uint64_t groups =
            (std::uint64_t(q.first) + q.count + outputsPerInvocation - 1) / outputsPerInvocation -
            q.first / outputsPerInvocation;
        const std::uint64_t invocations = std::uint64_t(i1.count) * i2.count * groups;
        if (invocations == 0) continue;
        sequence.dispatch(mPassKernel, buffers, params,
                          groupsFor(mContext, invocations, kWorkgroup));
    }
}

std::array<SeparableTransformKernels::Range, 3> SeparableTransformKernels::dofWindow(
    int normal, const CellBox& cells) const {
    std::array<Range, 3> window{};
    for (int a = 0; a < 3; ++a) {
        const std::uint32_t positions = mPositions[std::size_t(normal)][std::size_t(a)];
        window[std::size_t(a)] = {0, positions};
        if (a >= mDim) continue;
        // Along the normal the box's faces are one more than its cells; a walled axis's DOFs
        // start at its first inner face.
        const int faces = cells.count[std::size_t(a)] + (a == normal ? 1 : 0);
        const int first = cells.first[std::size_t(a)] - (a == normal && !mPeriodic[std::size_t(a)]);
        if (mPeriodic[std::size_t(a)] && (first < 0 || first + faces > mCells[std::size_t(a)]))
            continue;  // the box wraps: the whole axis
        const int from = std::clamp(first, 0, int(positions));
        const int to = std::clamp(first + faces, from, int(positions));
        window[std::size_t(a)] = {std::uint32_t(from), std::uint32_t(to - from)};
    }
    return window;
}

void SeparableTransformKernels::recordReconstruction(vulkan::CommandSequence& sequence,
                                                     const vulkan::DeviceBuffer& v,
                                                     const vulkan::DeviceBuffer& faceField,
                                                     const CellBox* needed) const {
    requireWords("separable_gather", v, mModeCount);
    requireWords("separable_pass", faceField, mFaceTotal);
    const std::uint32_t slots = std::uint32_t(mDim) * mSlotCount;
    const std::array<const vulkan::DeviceBuffer*, 4> scatter{&mScatterIndex, &mScatterWeight, &v,
                                                             &mSlots};
    sequence.dispatch(mGatherKernel, scatter, shaders::SeparableGatherParams{slots, 2, 0, 0},
                      groupsFor(mContext, slots, kWorkgroup));
    for (int normal = 0; normal < mDim; ++normal) {
        // A component's DOF positions are its face field positions (off the walls): the same
        // window as a projection's.
        const std::array<Range, 3> window =
            needed ? dofWindow(normal, *needed) : std::array<Range, 3>{};
        recordPasses(sequence, normal, true, mSlots, std::uint32_t(normal) * mSlotCount, faceField,
                     mFacePlacement[std::size_t(normal)], needed ? &window : nullptr);
    }
}

void SeparableTransformKernels::recordAnalysis(vulkan::CommandSequence& sequence,
                                               const vulkan::DeviceBuffer& q, FaceQuantity quantity,
                                               const vulkan::DeviceBuffer& f, int component,
                                               const CellBox* nonZero) const {
    requireWords("separable_pass", q, mDofCount);
    requireWords("separable_gather", f, mModeCount);
    // The skipped components' slots read as 0 in the gather (a fill of a few thousand words).
    if (component >= 0) sequence.fill(mSlots, VkDeviceSize(mDim) * mSlotCount * sizeof(float), 0u);
    for (int normal = 0; normal < mDim; ++normal)
        if (component < 0 || normal == component) {
            const std::array<Range, 3> window =
                nonZero ? dofWindow(normal, *nonZero) : std::array<Range, 3>{};
            recordPasses(sequence, normal, false, q, mDofStart[std::size_t(normal)], mSlots,
                         {std::uint32_t(normal) * mSlotCount}, nonZero ? &window : nullptr);
        }
    const auto& weights = mGatherWeights[quantity == FaceQuantity::Density ? 0 : 1];
    const std::array<const vulkan::DeviceBuffer*, 4> gather{&mGatherIndex, &weights, &mSlots, &f};
    sequence.dispatch(mGatherKernel, gather,
                      shaders::SeparableGatherParams{mModeCount, std::uint32_t(mDim), 0, 0},
                      groupsFor(mContext, mModeCount, kWorkgroup));
}

void SeparableTransformKernels::recordProjection(vulkan::CommandSequence& sequence,
                                                 const vulkan::DeviceBuffer& q,
                                                 const vulkan::DeviceBuffer& f) const {
    recordAnalysis(sequence, q, FaceQuantity::Density, f);
}

void SeparableTransformKernels::recordComponentProjection(vulkan::CommandSequence& sequence,
                                                          const vulkan::DeviceBuffer& q,
                                                          int component,
                                                          const vulkan::DeviceBuffer& f) const {
    if (component < 0 || component >= mDim)
        throw Error("separable projection: component " + std::to_string(component) + " of a " +
                    std::to_string(mDim) + "D field");
    recordAnalysis(sequence, q, FaceQuantity::Density, f, component);
}

void SeparableTransformKernels::recordFaceFieldProjection(vulkan::CommandSequence& sequence,
                                                          const vulkan::DeviceBuffer& q,
                                                          const vulkan::DeviceBuffer& f,
                                                          const CellBox* nonZero) const {
    recordAnalysis(sequence, q, FaceQuantity::FaceField, f, -1, nonZero);
}

}  // namespace modeflow::device
