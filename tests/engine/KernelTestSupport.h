#pragma once
/// @file KernelTestSupport.h
/// Small helpers of the reconstruction and force projection kernel tests: float32 copies,
/// device-rounded bases, read-backs, relative errors, and contexts with a lowered storage
/// buffer limit.

#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "engine/format/BasisCache.h"
#include "engine/device/ModeBuffer.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::testing {

inline std::vector<float> toFloat(std::span<const double> values) { return {values.begin(), values.end()}; }
inline std::vector<float> toFloat(const Eigen::VectorXd& v) { return {v.begin(), v.end()}; }
inline Eigen::VectorXd roundedToFloat(const Eigen::VectorXd& v) { return v.cast<float>().cast<double>(); }

/// The cache with its modes as a ModeBuffer of `precision` holds them (rounded, scaled back).
inline BasisCache withDeviceModes(const BasisCache& cache, ModePrecision precision) {
    BasisCache rounded = cache;
    rounded.velocity.modes = device::ModeBuffer::rounded(cache.velocity.modes, precision);
    return rounded;
}

/// A modal state on the device as the kernels take it: float32, zeros up to a multiple of 4.
inline vulkan::DeviceBuffer stateBuffer(const vulkan::VulkanContext& context, const Eigen::VectorXd& v,
                                        std::string name = "v") {
    std::vector<float> values = toFloat(v);
    values.resize((values.size() + 3) / 4 * 4, 0.0f);
    return vulkan::DeviceBuffer::fromValues<float>(context, values, std::move(name));
}

/// The first `count` floats of a buffer, as doubles.
inline Eigen::VectorXd downloadFloats(const vulkan::DeviceBuffer& buffer, std::size_t count) {
    std::vector<float> values(count);
    buffer.download<float>(values);
    return Eigen::Map<const Eigen::VectorXf>(values.data(), Eigen::Index(count)).cast<double>();
}

/// max |value − reference| / max |reference|.
inline double relativeError(const Eigen::VectorXd& value, const Eigen::VectorXd& reference) {
    return (value - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

/// A second context whose kernels may bind at most `limit` bytes per buffer.
inline std::unique_ptr<vulkan::VulkanContext> makeLimitedContext(bool validation, VkDeviceSize limit) {
    vulkan::VulkanContextOptions options;
    options.validation = validation;
    options.storageBufferLimit = limit;
    return std::make_unique<vulkan::VulkanContext>(options);
}

inline void expectNoValidationMessages(const vulkan::VulkanContext& context) {
    EXPECT_EQ(context.validationMessageCount(), 0u) << [&] {
        std::string all;
        for (const auto& m : context.validationMessages()) all += m + "\n";
        return all;
    }();
}

}  // namespace modeflow::testing
