#include "tests/support/KernelTestSupport.h"

namespace modeflow::testing {

std::vector<float> toFloat(std::span<const double> values) {
    return {values.begin(), values.end()};
}
std::vector<float> toFloat(const Eigen::VectorXd& v) {
    return {v.begin(), v.end()};
}

BasisCache withDeviceModes(const BasisCache& cache, ModePrecision precision) {
    BasisCache rounded = cache;
    rounded.velocity.modes = device::ModeBuffer::rounded(cache.velocity.modes, precision);
    return rounded;
}

vulkan::DeviceBuffer stateBuffer(const vulkan::VulkanContext& context, const Eigen::VectorXd& v,
                                 std::string name) {
    std::vector<float> values = toFloat(v);
    values.resize((values.size() + 3) / 4 * 4, 0.0f);
    return vulkan::DeviceBuffer::fromValues<float>(context, values, std::move(name));
}

Eigen::VectorXd downloadFloats(const vulkan::DeviceBuffer& buffer, std::size_t count) {
    std::vector<float> values(count);
    buffer.download<float>(values);
    return Eigen::Map<const Eigen::VectorXf>(values.data(), Eigen::Index(count)).cast<double>();
}

double relativeError(const Eigen::VectorXd& value, const Eigen::VectorXd& reference) {
    return (value - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

std::unique_ptr<vulkan::VulkanContext> makeLimitedContext(bool validation, VkDeviceSize limit) {
    vulkan::VulkanContextOptions options;
    options.validation = validation;
    options.storageBufferLimit = limit;
    return std::make_unique<vulkan::VulkanContext>(options);
}

}  // namespace modeflow::testing
