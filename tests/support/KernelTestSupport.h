#pragma once
/// @file KernelTestSupport.h
/// Small helpers of the reconstruction and force projection kernel tests: float32 copies,
/// device-rounded bases, read-backs, relative errors, and contexts with a lowered storage
/// buffer limit.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/device/ModeBuffer.h"
#include "engine/format/BasisCache.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::testing {

std::vector<float> toFloat(std::span<const double> values);
std::vector<float> toFloat(const Eigen::VectorXd& v);

/// The cache with its modes as a ModeBuffer of `precision` holds them (rounded, scaled back).
BasisCache withDeviceModes(const BasisCache& cache, ModePrecision precision);

/// A modal state on the device as the kernels take it: float32, zeros up to a multiple of 4.
vulkan::DeviceBuffer stateBuffer(const vulkan::VulkanContext& context, const Eigen::VectorXd& v,
                                 std::string name = "v");

/// The first `count` floats of a buffer, as doubles.
Eigen::VectorXd downloadFloats(const vulkan::DeviceBuffer& buffer, std::size_t count);

/// max |value − reference| / max |reference|.
double relativeError(const Eigen::VectorXd& value, const Eigen::VectorXd& reference);

/// A second context whose kernels may bind at most `limit` bytes per buffer.
std::unique_ptr<vulkan::VulkanContext> makeLimitedContext(bool validation, VkDeviceSize limit);

}  // namespace modeflow::testing
