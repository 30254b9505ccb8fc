#include "engine/device/DeviceCoefficients.h"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/device/DofFaces.h"
#include "engine/device/ModalKernels.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/dynamics/TensorFreeCoefficients.h"
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
                                       const StructuralCoefficients& coefficients,
                                       const BasisCache* cache, const ModeBuffer* modes,
                                       bool advection)
    : mN(coefficients.size()),
      mSubgroupsPerGroup(std::max(1u, 64u / context.subgroupSize())),
      mMaxGroups(groupCap(context)) {
    if (mN < 2) throw Error("modal contraction: needs at least 2 modes, got " + std::to_string(mN));
    const std::size_t n = std::size_t(mN);
    if (dynamic_cast<const TensorFreeCoefficients*>(&coefficients)) {
        if (!cache || cache->velocity.modes.cols() != mN)
            throw Error(
                "modal contraction: tensor-free coefficients on the device need their basis cache");
        mTensorFree.emplace(context, *cache, modes);
        mStreamedBytes = mTensorFree->streamedBytes();
        return;
    }
    // The N x N matrix of pair sums (modal_combine.comp), read as texels. Zero first: sparse
    // storage leaves the sums of pairs without entries, and the diagonal, untouched.
    requirePairSumsFit(context, mN);
    mPairSums.emplace(vulkan::DeviceBuffer::fromValues<float>(
        context, std::vector<float>(n * paddedSize(mN), 0.0f), "pair sums"));

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
            mChunks.push_back(
                {vulkan::DeviceBuffer::fromValues<float>(context, values, "coefficients"),
                 std::uint32_t(first), std::uint32_t(rows)});
        }
        mStreamedBytes = pairCount(n) * rowBytes;
        if (advection) mDenseAdvection.emplace(denseAdvection(context));
    } else if (const auto* sparse = dynamic_cast<const SparseCoefficients*>(&coefficients)) {
        if (sparse->nonZeros() == 0)
            throw Error(
                "modal contraction: the sparse coefficients have no entries (a basis without "
                "interactions)");
        mSparse.emplace(slicedRows(context, *sparse));
        mStreamedBytes = (sparse->nonZeros() + sparse->pairK().size()) * 8;
        if (advection) mSparseColumns.emplace(sparseColumns(context, *sparse));
    } else {
        throw Error(
            "modal contraction: the device takes dense, sparse or tensor-free coefficients only");
    }
}

void DeviceCoefficients::requirePairSumsFit(const vulkan::VulkanContext& context, int n) {
    const std::size_t sumBytes = std::size_t(n) * paddedSize(n) * sizeof(float);
    if (sumBytes > context.texelBufferLimit())
        throw Error("modal contraction: the pair sums of N = " + std::to_string(n) + " modes (" +
                    std::to_string(sumBytes) + " bytes) exceed the " +
                    std::to_string(context.texelBufferLimit()) + "-byte buffer limit of " +
                    context.deviceName() + "; use fewer modes or --device cpu");
}

/// The sparse rows in slices of kSliceRows (modal_pair_sums_sparse.comp): rows sorted by entry
/// count, longest first, so a slice's rows need about the same padding; within a slice, texel t
/// (entries 2t and 2t + 1) of each row side by side.
DeviceCoefficients::SparseRows DeviceCoefficients::slicedRows(const vulkan::VulkanContext& context,
                                                              const SparseCoefficients& sparse) {
    const std::size_t rows = sparse.pairK().size();
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
            records[4 * row] = std::uint32_t(sparse.pairK()[r]);
            records[4 * row + 1] = std::uint32_t(sliceStart);
            records[4 * row + 2] = std::uint32_t(texels);
            records[4 * row + 3] = std::uint32_t(sparse.pairJ()[r]);
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

DeviceCoefficients::SparseColumns DeviceCoefficients::sparseColumns(
    const vulkan::VulkanContext& context, const SparseCoefficients& sparse) {
    const std::size_t n = std::size_t(sparse.size());
    std::vector<std::uint32_t> start(n + 1, 0u);
    for (int i : sparse.columns()) ++start[std::size_t(i) + 1];
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> entries(4 * std::max<std::size_t>(sparse.nonZeros(), 1), 0u);
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t r = 0; r < sparse.pairK().size(); ++r)
        for (std::size_t t = sparse.rowStart()[r]; t < sparse.rowStart()[r + 1]; ++t) {
            const std::size_t at = 4 * std::size_t(next[std::size_t(sparse.columns()[t])]++);
            entries[at] = std::uint32_t(sparse.pairK()[r]);
            entries[at + 1] = std::uint32_t(sparse.pairJ()[r]);
            entries[at + 2] = std::bit_cast<std::uint32_t>(float(sparse.values()[t]));
        }
    return {vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, start, "sparse column starts"),
            vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, entries,
                                                            "sparse entries by column")};
}

DeviceCoefficients::DenseAdvection DeviceCoefficients::denseAdvection(
    const vulkan::VulkanContext& context) const {
    // Up to kGroups groups of tiles per chunk: enough partial rows to keep a device busy, few
    // enough that their sum is short.
    constexpr std::uint32_t kGroups = 64;
    std::vector<AdvectionGroups> chunks;
    std::uint32_t rows = 0;
    for (const Chunk& chunk : mChunks) {
        const std::uint32_t tiles = (chunk.pairs + kPairTileRows - 1) / kPairTileRows;
        const std::uint32_t perGroup = (tiles + kGroups - 1) / kGroups;
        const std::uint32_t groups = (tiles + perGroup - 1) / perGroup;
        chunks.push_back({rows, groups, perGroup});
        rows += groups;
    }
    const std::size_t n = std::size_t(mN);
    return {vulkan::DeviceBuffer::fromValues<float>(context, std::vector<float>(pairCount(n), 0.0f),
                                                    "pair weights"),
            vulkan::DeviceBuffer(context, VkDeviceSize(rows) * paddedSize(mN) * sizeof(float),
                                 "advection partial sums"),
            std::move(chunks), rows};
}

std::vector<std::uint32_t> DeviceCoefficients::advectGroups() const {
    if (mTensorFree) return mTensorFree->dispatchGroups();
    if (mSparseColumns) return {groupsFor(std::size_t(mN), 64, mMaxGroups)};
    if (!mDenseAdvection)
        throw Error("modal advection: the coefficients were uploaded without what advect needs");
    std::vector<std::uint32_t> groups{groupsFor(std::size_t(mN), 64, mMaxGroups)};
    for (const AdvectionGroups& chunk : mDenseAdvection->chunks)
        groups.push_back(
            groupsFor(std::size_t(chunk.groups) * (paddedSize(mN) / 8), 64, mMaxGroups));
    groups.push_back(groupsFor(std::size_t(mN), 64, mMaxGroups));
    return groups;
}

void DeviceCoefficients::recordAdvect(vulkan::CommandSequence& sequence,
                                      const ModalKernels& kernels, const vulkan::DeviceBuffer& u,
                                      const vulkan::DeviceBuffer& x,
                                      const vulkan::DeviceBuffer& out,
                                      IndirectArguments indirect) const {
    requireFloats(u, int(paddedSize(mN)));
    requireFloats(x, int(paddedSize(mN)));
    requireFloats(out, mN);
    if (mTensorFree) {
        mTensorFree->recordAdvect(sequence, u, x, out, indirect);
        return;
    }
    const std::vector<std::uint32_t> groups = advectGroups();
    const auto n = std::uint32_t(mN);
    if (mSparseColumns) {
        const std::array<const vulkan::DeviceBuffer*, 5> buffers{
            &mSparseColumns->start, &mSparseColumns->entries, &u, &x, &out};
        indirect.dispatch(sequence, kernels.advectSparse, buffers,
                          shaders::CombineParams{n, 0, 0, 0}, groups[0]);
        return;
    }
    std::uint32_t d = 0;
    const std::array<const vulkan::DeviceBuffer*, 3> weightBuffers{&u, &x,
                                                                   &mDenseAdvection->weights};
    indirect.after(d).dispatch(sequence, kernels.pairWeights, weightBuffers,
                               shaders::CombineParams{n, 0, 0, 0}, groups[d]);
    ++d;
    const auto octets = std::uint32_t(paddedSize(mN) / 8);
    for (std::size_t c = 0; c < mChunks.size(); ++c) {
        const AdvectionGroups& g = mDenseAdvection->chunks[c];
        const std::array<const vulkan::DeviceBuffer*, 3> buffers{
            &mChunks[c].values, &mDenseAdvection->weights, &mDenseAdvection->partial};
        indirect.after(d).dispatch(
            sequence, kernels.advectDense, buffers,
            shaders::AdvectDenseParams{octets, mChunks[c].firstPair, mChunks[c].pairs, g.firstGroup,
                                       g.tilesPerGroup, g.groups, 0, 0},
            groups[d]);
        ++d;
    }
    const std::array<const vulkan::DeviceBuffer*, 2> sumBuffers{&mDenseAdvection->partial, &out};
    indirect.after(d).dispatch(sequence, kernels.advectSum, sumBuffers,
                               shaders::AdvectSumParams{n, mDenseAdvection->rows, 8 * octets, 0},
                               groups[d]);
}

std::vector<std::uint32_t> DeviceCoefficients::dispatchGroups(bool sameVectors) const {
    if (mTensorFree) return mTensorFree->dispatchGroups(sameVectors);
    std::vector<std::uint32_t> groups = pairSumGroups();
    for (const std::uint32_t g : combineGroups()) groups.push_back(g);
    return groups;
}

void DeviceCoefficients::requireAssembled(const char* what) const {
    if (mTensorFree)
        throw Error(std::string("modal contraction: tensor-free coefficients keep no ") + what);
}

std::vector<std::uint32_t> DeviceCoefficients::pairSumGroups() const {
    requireAssembled("pair sums");
    std::vector<std::uint32_t> groups;
    if (mSparse) groups.push_back(groupsFor(mSparse->rowCount, 64, mMaxGroups));
    for (const Chunk& chunk : mChunks)
        // A tile per kPairTileLanes invocations of 64.
        groups.push_back(groupsFor(chunk.pairs, kPairTileRows * 64 / kPairTileLanes, mMaxGroups));
    return groups;
}

std::vector<std::uint32_t> DeviceCoefficients::combineGroups() const {
    requireAssembled("pair sums");
    return {groupsFor(std::size_t(mN), mSubgroupsPerGroup, mMaxGroups),
            groupsFor(paddedSize(mN) / 4, 64, mMaxGroups)};
}

void DeviceCoefficients::recordApply(vulkan::CommandSequence& sequence, const ModalKernels& kernels,
                                     const vulkan::DeviceBuffer& a, const vulkan::DeviceBuffer& b,
                                     const vulkan::DeviceBuffer& out,
                                     IndirectArguments indirect) const {
    if (mTensorFree) {
        requireFloats(a, int(paddedSize(mN)));
        requireFloats(b, int(paddedSize(mN)));
        requireFloats(out, mN);
        mTensorFree->recordApply(sequence, a, b, out, indirect);
        return;
    }
    recordPairSums(sequence, kernels, a, indirect);
    recordCombine(sequence, kernels, b, out, indirect.after(std::uint32_t(pairSumGroups().size())));
}

void DeviceCoefficients::recordPairSums(vulkan::CommandSequence& sequence,
                                        const ModalKernels& kernels, const vulkan::DeviceBuffer& a,
                                        IndirectArguments indirect) const {
    requireAssembled("pair sums");
    requireFloats(a, int(paddedSize(mN)));
    const std::vector<std::uint32_t> groups = pairSumGroups();
    std::uint32_t d = 0;
    const auto n = std::uint32_t(mN);
    if (mSparse) {
        const std::array<const vulkan::DeviceBuffer*, 4> buffers{&mSparse->rows, &mSparse->entries,
                                                                 &a, &*mPairSums};
        indirect.after(d).dispatch(
            sequence, kernels.sparsePairSums, buffers,
            shaders::SparsePairSumsParams{n, mSparse->rowCount, std::uint32_t(paddedSize(mN)), 0},
            groups[d]);
        ++d;
    }
    for (const Chunk& chunk : mChunks) {
        const std::array<const vulkan::DeviceBuffer*, 3> buffers{&chunk.values, &a, &*mPairSums};
        indirect.after(d).dispatch(sequence, kernels.pairSums, buffers,
                                   shaders::PairSumsParams{std::uint32_t(paddedSize(mN) / 8),
                                                           chunk.firstPair, chunk.pairs, n},
                                   groups[d]);
        ++d;
    }
}

void DeviceCoefficients::recordCombine(vulkan::CommandSequence& sequence,
                                       const ModalKernels& kernels, const vulkan::DeviceBuffer& b,
                                       const vulkan::DeviceBuffer& out,
                                       IndirectArguments indirect) const {
    requireAssembled("pair sums");
    requireFloats(b, int(paddedSize(mN)));
    requireFloats(out, mN);
    const std::vector<std::uint32_t> groups = combineGroups();
    const std::array<const vulkan::DeviceBuffer*, 3> buffers{&*mPairSums, &b, &out};
    const shaders::CombineParams combine{std::uint32_t(mN), std::uint32_t(paddedSize(mN) / 4), 0,
                                         0};
    indirect.dispatch(sequence, kernels.combine, buffers, combine, groups[0]);
    indirect.after(1).dispatch(sequence, kernels.combineColumns, buffers, combine, groups[1]);
}

}  // namespace modeflow::device
