#include "engine/device/TensorFreeAdvection.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>  // the generated headers use uint32_t without including it
#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/device/DofFaces.h"
#include "engine/simulation/ProjectionWeights.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/AdvectionParams.h"
#include "shaders/advection_gather.spv.h"
#include "shaders/advection_samples.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroup = 64;

/// The element table (AdvectionParams.h): per element the curl's four faces, the two of each
/// velocity component, then the eight coefficients, scaled by the faces' areas (a face field
/// holds flux / area). Unused slots: face 0, coefficient 0.
std::vector<std::uint32_t> elementTable(const BasisCache& cache) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const BasisCache::Quadrature& q = cache.quadrature;
    const std::int64_t elements = q.curl.rows();
    std::vector<std::uint32_t> table(std::size_t(elements) * ADVECTION_ELEMENT_TEXELS * 4, 0u);
    const auto fill = [&](const SparseRows& rows, std::int64_t e, std::size_t first,
                          std::size_t slots, const char* what) {
        const std::int64_t count = rows.start[e + 1] - rows.start[e];
        if (count > std::int64_t(slots))
            throw Error(std::string("tensor-free advection: vorticity element ") +
                        std::to_string(e) + " has " + std::to_string(count) + " " + what +
                        " samples, the device takes " + std::to_string(slots));
        std::uint32_t* record = table.data() + std::size_t(e) * ADVECTION_ELEMENT_TEXELS * 4;
        for (std::int64_t t = 0; t < count; ++t) {
            const std::int64_t face = cache.faces[std::size_t(rows.column[rows.start[e] + t])];
            const double area = grid.faceArea(locateFace(grid, face).axis);
            record[first + std::size_t(t)] = std::uint32_t(face);
            record[8 + first + std::size_t(t)] =
                std::bit_cast<std::uint32_t>(float(rows.value[rows.start[e] + t] * area));
        }
    };
    for (std::int64_t e = 0; e < elements; ++e) {
        fill(q.curl, e, 0, 4, "curl");
        fill(q.velocityB, e, 4, 2, "first velocity");
        fill(q.velocityC, e, 6, 2, "second velocity");
    }
    return table;
}

/// Σ over `parts` of (rows transposed, sample slot 2e + offset), per DOF, coefficients divided by
/// the projection weights.
struct Part {
    const SparseRows* rows;
    std::uint32_t offset;
};

std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> gatherTable(
    const BasisCache& cache, std::initializer_list<Part> parts) {
    const Eigen::VectorXd weights = projectionWeights(cache, FaceQuantity::Density);
    const std::size_t dofs = cache.faces.size();
    std::vector<std::uint32_t> start(dofs + 1, 0u);
    for (const Part& part : parts)
        for (std::int32_t c : part.rows->column) ++start[std::size_t(c) + 1];
    for (std::size_t d = 0; d < dofs; ++d) start[d + 1] += start[d];
    std::vector<std::uint32_t> entries(2 * std::size_t(start.back()));
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const Part& part : parts)
        for (std::int64_t e = 0; e < part.rows->rows(); ++e)
            for (std::int64_t t = part.rows->start[e]; t < part.rows->start[e + 1]; ++t) {
                const auto d = std::size_t(part.rows->column[t]);
                const std::size_t at = 2 * std::size_t(next[d]++);
                entries[at] = std::uint32_t(2 * e) + part.offset;
                entries[at + 1] = std::bit_cast<std::uint32_t>(
                    float(part.rows->value[t] / weights[Eigen::Index(d)]));
            }
    if (entries.empty()) entries.assign(2, 0u);  // a buffer needs bytes
    return {std::move(start), std::move(entries)};
}

const ModeBuffer& checkedModes(const ModeBuffer* modes, const BasisCache& cache) {
    if (modes->precision() != ModePrecision::Float32 || modes->dofCount() != cache.faces.size() ||
        modes->modeCount() != std::uint32_t(cache.velocity.modes.cols()))
        throw Error("tensor-free advection: the device basis given is not this basis in float32");
    return *modes;
}

std::int64_t checkedElements(const BasisCache& cache) {
    const std::int64_t elements = cache.quadrature.curl.rows();
    if (elements < 1)
        throw Error("tensor-free advection: the basis cache holds no vorticity quadrature");
    if (elements > std::int64_t(UINT32_MAX / 2))
        throw Error("tensor-free advection: " + std::to_string(elements) +
                    " vorticity elements exceed the kernels' 32-bit slots");
    return elements;
}

}  // namespace

TensorFreeAdvection::TensorFreeAdvection(const vulkan::VulkanContext& context,
                                         const BasisCache& cache, const ModeBuffer* modes)
    : mContext(context),
      mReconstruction(context, cache),
      mProjection(context, cache, FaceQuantity::Density),
      mElementCount(std::uint32_t(checkedElements(cache))),
      mDofCount(std::uint32_t(cache.faces.size())),
      mElements(vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, elementTable(cache),
                                                                "advection elements")),
      mApplyGather([&] {
          const auto [start, entries] = gatherTable(
              cache, {{&cache.quadrature.velocityB, 0}, {&cache.quadrature.velocityC, 1}});
          return Gather{
              vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, start, "advection rows"),
              vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, entries,
                                                              "advection entries")};
      }()),
      mAdvectGather([&] {
          const auto [start, entries] = gatherTable(cache, {{&cache.quadrature.curl, 0}});
          return Gather{
              vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, start, "induction rows"),
              vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, entries,
                                                              "induction entries")};
      }()),
      mFieldA(mReconstruction.makeFaceField("advection field a")),
      mFieldB(mReconstruction.makeFaceField("advection field b")),
      mSamples(context, VkDeviceSize(mElementCount) * 2 * sizeof(float), "advection samples"),
      mProjected(context,
                 VkDeviceSize(std::max<std::size_t>(cache.faces.size(), 4)) * sizeof(float),
                 "advection per DOF"),
      mApplySamples(context, {"advection_samples",
                              advection_samples_spv,
                              4,
                              sizeof(shaders::AdvectionSampleParams),
                              kWorkgroup,
                              {ADVECTION_APPLY},
                              {0}}),
      mAdvectSamples(context, {"advection_samples",
                               advection_samples_spv,
                               4,
                               sizeof(shaders::AdvectionSampleParams),
                               kWorkgroup,
                               {ADVECTION_ADVECT},
                               {0}}),
      mGatherKernel(context, {"advection_gather", advection_gather_spv, 4,
                              sizeof(shaders::AdvectionGatherParams), kWorkgroup}) {
    if (modes) {
        mModes = &checkedModes(modes, cache);
    } else {
        mOwnModes.emplace(context, cache.velocity.modes, ModePrecision::Float32);
        mModes = &*mOwnModes;
    }
}

std::size_t TensorFreeAdvection::streamedBytes() const {
    return 2 * std::size_t(mModes->modeStride()) * mModes->modeCount() * sizeof(float) +
           mElements.bytes() + mApplyGather.rowStart.bytes() + mApplyGather.entries.bytes();
}

std::vector<std::uint32_t> TensorFreeAdvection::dispatchGroups(bool sameVectors) const {
    std::vector<std::uint32_t> groups = mReconstruction.dispatchGroups(*mModes);
    if (!sameVectors) groups.insert(groups.end(), groups.begin(), groups.end());  // a, then b
    groups.push_back(groupsFor(mContext, mElementCount, kWorkgroup));
    groups.push_back(groupsFor(mContext, mDofCount, kWorkgroup));
    const std::vector<std::uint32_t> projection = mProjection.dispatchGroups(*mModes);
    groups.insert(groups.end(), projection.begin(), projection.end());
    return groups;
}

void TensorFreeAdvection::recordApply(vulkan::CommandSequence& sequence,
                                      const vulkan::DeviceBuffer& a, const vulkan::DeviceBuffer& b,
                                      const vulkan::DeviceBuffer& out,
                                      IndirectArguments indirect) const {
    record(sequence, true, a, b, out, indirect);
}

void TensorFreeAdvection::recordAdvect(vulkan::CommandSequence& sequence,
                                       const vulkan::DeviceBuffer& u, const vulkan::DeviceBuffer& x,
                                       const vulkan::DeviceBuffer& out,
                                       IndirectArguments indirect) const {
    record(sequence, false, u, x, out, indirect);
}

void TensorFreeAdvection::record(vulkan::CommandSequence& sequence, bool apply,
                                 const vulkan::DeviceBuffer& a, const vulkan::DeviceBuffer& b,
                                 const vulkan::DeviceBuffer& out,
                                 IndirectArguments indirect) const {
    const bool same = &a == &b;
    const std::vector<std::uint32_t> groups = dispatchGroups(same);
    const auto chunks = std::uint32_t(mModes->chunks().size());
    mReconstruction.record(sequence, *mModes, a, mFieldA, indirect);
    if (!same) mReconstruction.record(sequence, *mModes, b, mFieldB, indirect.after(chunks));
    std::uint32_t d = same ? chunks : 2 * chunks;
    const std::array<const vulkan::DeviceBuffer*, 4> sampleBuffers{
        &mElements, &mFieldA, same ? &mFieldA : &mFieldB, &mSamples};
    indirect.after(d).dispatch(sequence, apply ? mApplySamples : mAdvectSamples, sampleBuffers,
                               shaders::AdvectionSampleParams{mElementCount, 0, 0, 0}, groups[d]);
    ++d;
    const Gather& gather = apply ? mApplyGather : mAdvectGather;
    const std::array<const vulkan::DeviceBuffer*, 4> gatherBuffers{
        &gather.rowStart, &gather.entries, &mSamples, &mProjected};
    indirect.after(d).dispatch(sequence, mGatherKernel, gatherBuffers,
                               shaders::AdvectionGatherParams{mDofCount, 0, 0, 0}, groups[d]);
    ++d;
    mProjection.record(sequence, *mModes, mProjected, out, indirect.after(d));
}

}  // namespace modeflow::device
