#include "engine/device/ModeBuffer.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <string>

#include "engine/core/Error.h"
#include "engine/device/HalfFloat.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::device {
namespace {

std::uint32_t checkedDofCount(const Eigen::MatrixXd& modes) {
    if (modes.rows() == 0 || modes.cols() == 0)
        throw Error("mode buffer: the basis is empty (" + std::to_string(modes.rows()) + " DOFs, " +
                    std::to_string(modes.cols()) + " modes)");
    if (modes.rows() > Eigen::Index(std::numeric_limits<std::uint32_t>::max()) ||
        modes.cols() > Eigen::Index(std::numeric_limits<std::uint32_t>::max()))
        throw Error("mode buffer: " + std::to_string(modes.rows()) + " DOFs × " +
                    std::to_string(modes.cols()) + " modes do not fit 32-bit indices");
    return std::uint32_t(modes.rows());
}

/// The factor each stored mode is multiplied by: its max |value| for float16 (the stored values
/// then lie in [−1, 1], clear of float16's subnormals), 1 for float32.
std::vector<float> modeScales(const Eigen::MatrixXd& modes, ModePrecision precision) {
    std::vector<float> scales(std::size_t(modes.cols()), 1.0f);
    if (precision == ModePrecision::Float16)
        for (Eigen::Index i = 0; i < modes.cols(); ++i) {
            const auto largest = float(modes.col(i).lpNorm<Eigen::Infinity>());
            if (largest > 0.0f) scales[std::size_t(i)] = largest;
        }
    return scales;
}

/// modeScales with zeros up to a multiple of 4 (read as vec4s).
std::vector<float> paddedScales(const Eigen::MatrixXd& modes, ModePrecision precision) {
    std::vector<float> scales = modeScales(modes, precision);
    scales.resize((scales.size() + 3) / 4 * 4, 0.0f);
    return scales;
}

/// 32-bit words per mode: whole tiles of 16-byte vectors of 4 float32 or 8 float16 values.
std::uint32_t modeStrideFor(std::uint64_t dofs, ModePrecision precision) {
    const std::uint64_t perTile =
        std::uint64_t(ModeBuffer::dofsPerVector(precision)) * ModeBuffer::kTileVectors;
    return std::uint32_t((dofs + perTile - 1) / perTile * ModeBuffer::kTileVectors * 4);
}

/// Writes one mode's stored words, in DOF order, to `words` (zero-filled up to the mode stride by
/// the caller).
void encodeMode(const Eigen::Ref<const Eigen::VectorXd>& mode, float scale, ModePrecision precision,
                std::uint32_t* words) {
    if (precision == ModePrecision::Float32) {
        for (Eigen::Index d = 0; d < mode.size(); ++d)
            words[d] = std::bit_cast<std::uint32_t>(float(mode[d]));
        return;
    }
    for (Eigen::Index d = 0; d < mode.size(); d += 2) {
        const std::uint32_t low = floatToHalf(float(mode[d] / scale));
        const std::uint32_t high =
            d + 1 < mode.size() ? floatToHalf(float(mode[d + 1] / scale)) : 0u;
        words[d / 2] = low | (high << 16);
    }
}

}  // namespace

ModeBuffer::ModeBuffer(const vulkan::VulkanContext& context, const Eigen::MatrixXd& modes,
                       ModePrecision precision)
    : mDofCount(checkedDofCount(modes)),
      mModeCount(std::uint32_t(modes.cols())),
      mPrecision(precision),
      mModeStride(modeStrideFor(mDofCount, precision)),
      mScales(vulkan::DeviceBuffer::fromValues<float>(context, paddedScales(modes, precision),
                                                      "mode scales")) {
    const VkDeviceSize modeBytes = VkDeviceSize(mModeStride) * sizeof(std::uint32_t);
    // The kernels read a chunk as texels: within the texel limit too.
    const VkDeviceSize limit = context.texelBufferLimit();
    if (modeBytes > limit)
        throw Error("mode buffer: one mode takes " + std::to_string(modeBytes) +
                    " bytes, more than the " + std::to_string(limit) + "-byte buffer limit of " +
                    context.deviceName());
    // A multiple of 4 modes per chunk where 4 fit, so the kernels' reads of four modes' state
    // values at a time never straddle two chunks (they handle it where the limit forces it).
    auto perChunk = std::uint32_t(std::min<VkDeviceSize>(mModeCount, limit / modeBytes));
    if (perChunk < mModeCount && perChunk >= 4) perChunk -= perChunk % 4;
    const std::vector<float> scales = modeScales(modes, precision);
    for (std::uint32_t first = 0; first < mModeCount; first += perChunk) {
        const std::uint32_t count = std::min(perChunk, mModeCount - first);
        // Tile-major: tile t of every mode of the chunk, then tile t + 1 (see the header).
        const std::size_t tileWords = std::size_t(kTileVectors) * 4,
                          tiles = mModeStride / tileWords;
        std::vector<std::uint32_t> mode(mModeStride), words(std::size_t(count) * mModeStride);
        for (std::uint32_t i = 0; i < count; ++i) {
            std::fill(mode.begin(), mode.end(), 0u);
            encodeMode(modes.col(first + i), scales[first + i], precision, mode.data());
            for (std::size_t t = 0; t < tiles; ++t)
                std::copy_n(mode.begin() + std::ptrdiff_t(t * tileWords), tileWords,
                            words.begin() + std::ptrdiff_t((t * count + i) * tileWords));
        }
        const std::string name =
            "modes " + std::to_string(first) + "-" + std::to_string(first + count - 1);
        mChunks.push_back(Chunk{
            first, count, vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, words, name)});
    }
}

Eigen::MatrixXd ModeBuffer::rounded(const Eigen::MatrixXd& modes, ModePrecision precision) {
    const std::vector<float> scales = modeScales(modes, precision);
    Eigen::MatrixXd result(modes.rows(), modes.cols());
    std::vector<std::uint32_t> words(modeStrideFor(std::uint64_t(modes.rows()), precision));
    for (Eigen::Index i = 0; i < modes.cols(); ++i) {
        encodeMode(modes.col(i), scales[std::size_t(i)], precision, words.data());
        for (Eigen::Index d = 0; d < modes.rows(); ++d) {
            const double stored =
                precision == ModePrecision::Float32
                    ? double(std::bit_cast<float>(words[std::size_t(d)]))
                    : double(
                          halfToFloat(std::uint16_t(words[std::size_t(d / 2)] >> (16 * (d % 2)))));
            result(d, i) = stored * scales[std::size_t(i)];
        }
    }
    return result;
}

}  // namespace modeflow::device
