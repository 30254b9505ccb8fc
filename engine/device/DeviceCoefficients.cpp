#include "engine/device/DeviceCoefficients.h"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>
#include <string>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/core/Error.h"
#include "engine/device/ModalKernels.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ModalStepParams.h"

namespace modeflow::device {
namespace {

void requireFloats(const vulkan::DeviceBuffer& buffer, int n) {
    if (buffer.bytes() < std::size_t(n) * sizeof(float))
        throw Error("modal contraction: buffer \"" + buffer.name() + "\" holds " +
                    std::to_string(buffer.bytes()) + " bytes, " +
                    std::to_string(n * sizeof(float)) + " needed for N = " + std::to_string(n));
}

constexpr std::size_t kPairTileRows = PAIR_TILE_ROWS, kPairTileLanes = PAIR_TILE_LANES;
/// Rows of a slice of the sparse layout: one 8-wide batch of invocations on lavapipe.
constexpr std::size_t kSliceRows = PAIR_TILE_LANES;

std::uint32_t groupsFor(std::size_t items, std::size_t perGroup, std::uint32_t maxGroups) {
    return std::uint32_t(std::clamp<std::size_t>((items + perGroup - 1) / perGroup, 1, maxGroups));
}

}  // namespace

DeviceCoefficients::DeviceCoefficients(const vulkan::VulkanContext& context,
                                       const StructuralCoefficients& coefficients)
    : mN(coefficients.size()),
      mSubgroupsPerGroup(std::max(1u, 64u / context.subgroupSize())),
      mMaxGroups(context.properties().limits.maxComputeWorkGroupCount[0]) {
    if (mN < 2) throw Error("modal contraction: needs at least 2 modes, got " + std::to_string(mN));
    const std::size_t n = std::size_t(mN);
    // Zero first: sparse storage leaves the sums of pairs without entries untouched.
    mPairSums.emplace(vulkan::DeviceBuffer::fromValues<float>(
        context, std::vector<float>(pairCount(n), 0.0f), "pair sums"));

    if (const auto* dense = dynamic_cast<const DenseCoefficients*>(&coefficients)) {
        const std::size_t rowOctets = paddedSize(mN) / 8, rowBytes = paddedSize(mN) * sizeof(float);
        const std::size_t tileBytes = kPairTileRows * rowBytes;
        // The pair sums read a chunk as texels: within the texel limit too.
        const std::size_t rowsPerChunk = context.texelBufferLimit() / tileBytes * kPairTileRows;
        if (rowsPerChunk == 0)
            throw Error("modal contraction: " + std::to_string(kPairTileRows) +
                        " rows of N = " + std::to_string(n) + " coefficients exceed the " +
                        std::to_string(context.texelBufferLimit()) + "-byte buffer limit of " +
                        context.deviceName());
        const std::vector<double>& packed = dense->packed();
        for (std::size_t first = 0; first < pairCount(n); first += rowsPerChunk) {
            const std::size_t rows = std::min(rowsPerChunk, pairCount(n) - first);
            // Tiles of kPairTileRows rows, octet-interleaved (modal_pair_sums.comp): coefficient i
            // of row j of tile t at ((t rowOctets + i / 8) kPairTileRows + j) 8 + i % 8.
            const std::size_t tiles = (rows + kPairTileRows - 1) / kPairTileRows;
            std::vector<float> values(tiles * tileBytes / sizeof(float), 0.0f);
            for (std::size_t r = 0; r < rows; ++r) {
                const std::size_t tile = r / kPairTileRows, j = r % kPairTileRows;
                for (std::size_t i = 0; i < n; ++i)
                    values[((tile * rowOctets + i / 8) * kPairTileRows + j) * 8 + i % 8] =
                        float(packed[(first + r) * n + i]);
            }
            mChunks.push_back({vulkan::DeviceBuffer::fromValues<float>(context, values, "coefficients"),
                               std::uint32_t(first), std::uint32_t(rows)});
        }
        mStreamedBytes = pairCount(n) * rowBytes;
    } else if (const auto* sparse = dynamic_cast<const SparseCoefficients*>(&coefficients)) {
        if (sparse->nonZeros() == 0)
            throw Error(
                "modal contraction: the sparse coefficients have no entries (a basis without "
                "interactions)");
        mSparse.emplace(slicedRows(context, *sparse));
        mStreamedBytes = (sparse->nonZeros() + sparse->pairK().size()) * 8;
    } else {
        throw Error("modal contraction: the device takes dense or sparse coefficients only");
    }
}

/// The sparse rows in slices of kSliceRows (modal_pair_sums_sparse.comp): rows sorted by entry
/// count, longest first, so a slice's rows need about the same padding; within a slice, texel t
/// (entries 2t and 2t + 1) of each row side by side.
DeviceCoefficients::SparseRows DeviceCoefficients::slicedRows(const vulkan::VulkanContext& context,
                                                              const SparseCoefficients& sparse) {
    const std::size_t rows = sparse.pairK().size(), n = std::size_t(sparse.size());
    const auto length = [&](std::size_t r) {
        return sparse.rowStart()[r + 1] - sparse.rowStart()[r];
    };
    std::vector<std::size_t> order(rows);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return length(a) > length(b); });

    std::vector<std::uint32_t> records(rows * 4, 0u), entries;
    for (std::size_t first = 0; first < rows; first += kSliceRows) {
        const std::size_t texels = (length(order[first]) + 1) / 2;  // the slice's longest row
        const std::size_t sliceStart = entries.size() / 4;
        entries.resize(entries.size() + texels * kSliceRows * 4, 0u);  // padding: column 0, value 0
        for (std::size_t lane = 0; lane < kSliceRows && first + lane < rows; ++lane) {
            const std::size_t r = order[first + lane], row = first + lane;
            records[4 * row] = std::uint32_t(
                pairIndex(n, std::size_t(sparse.pairK()[r]), std::size_t(sparse.pairJ()[r])));
            records[4 * row + 1] = std::uint32_t(sliceStart);
            records[4 * row + 2] = std::uint32_t(texels);
            for (std::size_t e = 0; e < length(r); ++e) {
                const std::size_t source = sparse.rowStart()[r] + e;
                const std::size_t word =
                    ((sliceStart + (e / 2) * kSliceRows + lane) * 2 + e % 2) * 2;
                entries[word] = std::uint32_t(sparse.columns()[source]);
                entries[word + 1] = std::bit_cast<std::uint32_t>(float(sparse.values()[source]));
            }
        }
    }
    return {vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, records, "sparse rows"),
            vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, entries, "sparse entries"),
            std::uint32_t(rows)};
}

std::vector<std::uint32_t> DeviceCoefficients::dispatchGroups() const {
    std::vector<std::uint32_t> groups;
    if (mSparse) groups.push_back(groupsFor(mSparse->rowCount, 64, mMaxGroups));
    for (const Chunk& chunk : mChunks)
        // A tile per kPairTileLanes invocations of 64.
        groups.push_back(groupsFor(chunk.pairs, kPairTileRows * 64 / kPairTileLanes, mMaxGroups));
    groups.push_back(groupsFor(std::size_t(mN), mSubgroupsPerGroup, mMaxGroups));
    return groups;
}

void DeviceCoefficients::recordApply(vulkan::CommandSequence& sequence, const ModalKernels& kernels,
                                     const vulkan::DeviceBuffer& a, const vulkan::DeviceBuffer& b,
                                     const vulkan::DeviceBuffer& out, IndirectArguments indirect) const {
    requireFloats(a, int(paddedSize(mN)));
    requireFloats(b, mN);
    requireFloats(out, mN);
    const std::vector<std::uint32_t> groups = dispatchGroups();
    std::size_t d = 0;
    const auto dispatch = [&](const vulkan::ComputeKernel& kernel,
                              std::span<const vulkan::DeviceBuffer* const> buffers, const auto& params) {
        if (indirect.buffer)
            sequence.dispatchIndirect(
                kernel, buffers, params, *indirect.buffer,
                VkDeviceSize(indirect.first + d) * sizeof(VkDispatchIndirectCommand));
        else
            sequence.dispatch(kernel, buffers, params, groups[d]);
        ++d;
    };
    const auto n = std::uint32_t(mN);
    if (mSparse) {
        const std::array<const vulkan::DeviceBuffer*, 4> buffers{&mSparse->rows, &mSparse->entries, &a,
                                                         &*mPairSums};
        dispatch(kernels.sparsePairSums, buffers,
                 shaders::SparsePairSumsParams{n, mSparse->rowCount, 0, 0});
    }
    for (const Chunk& chunk : mChunks) {
        const std::array<const vulkan::DeviceBuffer*, 3> buffers{&chunk.values, &a, &*mPairSums};
        dispatch(kernels.pairSums, buffers,
                 shaders::PairSumsParams{std::uint32_t(paddedSize(mN) / 8), chunk.firstPair,
                                         chunk.pairs, 0});
    }
    const std::array<const vulkan::DeviceBuffer*, 3> buffers{&*mPairSums, &b, &out};
    dispatch(kernels.combine, buffers, shaders::CombineParams{n, 0, 0, 0});
}

}  // namespace modeflow::device
