#include "engine/device/ModalKernels.h"

// The generated headers use uint32_t without including <cstdint>.
#include <cstdint>

#include "engine/core/Error.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ModalStepParams.h"
#include "shaders/modal_advect_dense.spv.h"
#include "shaders/modal_advect_sparse.spv.h"
#include "shaders/modal_advect_sum.spv.h"
#include "shaders/modal_combine.spv.h"
#include "shaders/modal_combine_columns.spv.h"
#include "shaders/modal_linear.spv.h"
#include "shaders/modal_pair_sums.spv.h"
#include "shaders/modal_pair_sums_sparse.spv.h"
#include "shaders/modal_pair_weights.spv.h"
#include "shaders/modal_update.spv.h"

namespace modeflow::device {
namespace {

const vulkan::VulkanContext& requireFeatures(const vulkan::VulkanContext& context) {
    if (!context.hasSubgroupArithmetic())
        throw Error("Vulkan device " + context.deviceName() +
                    " lacks subgroup arithmetic in compute shaders, which the modal step needs; "
                    "run with --device cpu");
    return context;
}

/// The update is one workgroup over the state. A CPU device runs its subgroups one after the
/// other between barriers, so fewer lanes cost less there (64 as fast as 32, 256 slower on
/// lavapipe: precompute/README.md "Closed-form bases"); a GPU wants them all.
std::uint32_t updateWorkgroupSize(const vulkan::VulkanContext& context) {
    return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 64 : 256;
}

}  // namespace

ModalKernels::ModalKernels(const vulkan::VulkanContext& context)
    : pairSums(requireFeatures(context), {"modal_pair_sums",
                                          modal_pair_sums_spv,
                                          3,
                                          sizeof(shaders::PairSumsParams),
                                          64,
                                          {},
                                          {0, 1}}),
      sparsePairSums(context, {"modal_pair_sums_sparse",
                               modal_pair_sums_sparse_spv,
                               4,
                               sizeof(shaders::SparsePairSumsParams),
                               64,
                               {},
                               {0, 1},
                               {},
                               {2}}),
      combine(
          context,
          {"modal_combine", modal_combine_spv, 3, sizeof(shaders::CombineParams), 64, {}, {0, 1}}),
      combineColumns(context, {"modal_combine_columns",
                               modal_combine_columns_spv,
                               3,
                               sizeof(shaders::CombineParams),
                               64,
                               {},
                               {0, 1}}),
      pairWeights(context, {"modal_pair_weights", modal_pair_weights_spv, 3,
                            sizeof(shaders::CombineParams), 64}),
      advectDense(context, {"modal_advect_dense",
                            modal_advect_dense_spv,
                            3,
                            sizeof(shaders::AdvectDenseParams),
                            64,
                            {},
                            {0}}),
      advectSum(context, {"modal_advect_sum", modal_advect_sum_spv, 2,
                          sizeof(shaders::AdvectSumParams), 64}),
      advectSparse(context, {"modal_advect_sparse", modal_advect_sparse_spv, 5,
                             sizeof(shaders::CombineParams), 64}),
      linear(context,
             {"modal_linear", modal_linear_spv, 3, sizeof(shaders::CombineParams), 64, {}, {0, 1}}),
      mUpdates(context, {"modal_update", modal_update_spv, 12, sizeof(shaders::ModalUpdateParams),
                         updateWorkgroupSize(context)}) {}

const vulkan::ComputeKernel& ModalKernels::update(std::uint32_t op, bool frozen,
                                                  bool lorentz) const {
    return mUpdates.with({op, frozen ? 1u : 0u, lorentz ? 1u : 0u});
}

}  // namespace modeflow::device
