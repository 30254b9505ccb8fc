#pragma once
/// @file DeviceCoefficients.h
/// Structural coefficients on the device, float32, and the contraction out = C(a, b), i.e.
/// out_k = Σ_ij C[k][i][j] a_i b_j (CPU reference: StructuralCoefficients::apply), in two passes
/// that read every stored coefficient once:
///   1. pair sums  s(k,j) = Σ_i C[k][i][j] a_i for every pair k < j (a GEMV over the packed rows),
///   2. combine    out_k = Σ_{j>k} s(k,j) b_j − Σ_{j<k} s(j,k) b_j   (antisymmetry): the first
///      pass writes s into the upper triangle of an N × N matrix U, and out = U b − Uᵀ b in two
///      passes over U read as texels (shaders/ModalCombine.glsl has why).
/// Dense coefficients are stored in tiles of PAIR_TILE_ROWS pair rows (shaders/modal_pair_sums.comp
/// has the layout and why) and split into chunks of whole tiles when they exceed the device's
/// buffer limit (VulkanContext::texelBufferLimit; lavapipe: 128 MiB, i.e. N ≳ 400); sparse ones
/// are uploaded in slices of PAIR_TILE_LANES rows (shaders/modal_pair_sums_sparse.comp).
/// Tensor-free coefficients store nothing: the contraction runs TensorFreeAdvection's kernels on
/// the basis and the quadrature.

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/device/IndirectArguments.h"
#include "engine/device/TensorFreeAdvection.h"
#include "engine/format/BasisCache.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow {
class SparseCoefficients;
class StructuralCoefficients;
}  // namespace modeflow

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

struct ModalKernels;

/// Floats of a modal vector buffer: N rounded up to a multiple of 8. The pair-sum kernel reads
/// rows and the vector `a` eight floats per load (lavapipe turns each load into a per-lane
/// access, so wider loads are what gets it near memory bandwidth); rows and vectors are
/// zero-padded to that length.
constexpr std::size_t paddedSize(int n) {
    return (std::size_t(n) + 7) / 8 * 8;
}

class DeviceCoefficients {
public:
    /// Uploads `coefficients` (DenseCoefficients or SparseCoefficients) rounded to float32; for
    /// TensorFreeCoefficients, the tables of TensorFreeAdvection for `cache` (required then, and
    /// `modes` as TensorFreeAdvection takes it). `advection`: also what recordAdvect needs (the
    /// dense pair weights and partial sums, the sparse entries by column).
    /// @throw modeflow::Error for another storage, fewer than 2 modes, a single pair row or the
    /// sparse arrays above the storage buffer limit, tensor-free coefficients without their
    /// cache, or a failed allocation.
    DeviceCoefficients(const vulkan::VulkanContext& context,
                       const StructuralCoefficients& coefficients,
                       const BasisCache* cache = nullptr, const ModeBuffer* modes = nullptr,
                       bool advection = false);

    /// Assembled (dense or sparse) coefficients are contracted through an N × N matrix of pair
    /// sums read as texels: refuses an N whose matrix exceeds the device's texel buffer limit
    /// (lavapipe: 128 MB, N ≈ 5790), so a run can be refused before its cache is read.
    /// @throw modeflow::Error naming N, the bytes, the limit and the device.
    static void requirePairSumsFit(const vulkan::VulkanContext& context, int n);

    int size() const { return mN; }
    bool isSparse() const { return mSparse.has_value(); }
    bool isTensorFree() const { return mTensorFree.has_value(); }
    std::size_t chunkCount() const { return mChunks.size(); }
    /// Bytes of coefficient data (values and indices) one contraction reads; sparse: as CSR,
    /// 8 bytes per entry and per row (the slices' padding not counted).
    std::size_t streamedBytes() const { return mStreamedBytes; }

    /// Group counts of the dispatches recordApply makes, in order (pair-sum dispatches, then
    /// combine): what an IndirectArguments buffer must hold.
    /// `sameVectors`: recordApply's a and b are one buffer (tensor-free: one reconstruction).
    std::vector<std::uint32_t> dispatchGroups(bool sameVectors = false) const;

    /// Group counts of the dispatches recordAdvect makes, in order.
    std::vector<std::uint32_t> advectGroups() const;
    /// Records out_k = Σ_ij C[j][k][i] x_i u_j (StructuralCoefficients::advect; MHD's induction).
    /// @throw modeflow::Error unless constructed with `advection`, or for buffers too small.
    void recordAdvect(vulkan::CommandSequence& sequence, const ModalKernels& kernels,
                      const vulkan::DeviceBuffer& u, const vulkan::DeviceBuffer& x,
                      const vulkan::DeviceBuffer& out, IndirectArguments indirect = {}) const;

    /// Records out = C(a, b) (dispatchGroups().size() dispatches): recordPairSums, then
    /// recordCombine, for assembled coefficients.
    /// @throw modeflow::Error if `a` or `b` holds fewer than paddedSize(N) floats (zeros past N)
    /// or `out` fewer than N.
    void recordApply(vulkan::CommandSequence& sequence, const ModalKernels& kernels,
                     const vulkan::DeviceBuffer& a, const vulkan::DeviceBuffer& b,
                     const vulkan::DeviceBuffer& out, IndirectArguments indirect = {}) const;

    /// Assembled coefficients: the contraction's two halves, so that one set of pair sums (C with
    /// `a` frozen) serves several combines (the linearized rule, engine/device/ModalStepper.h).
    /// The pair sums live in this object until the next recordPairSums or recordApply.
    /// @throw modeflow::Error for tensor-free coefficients (they keep no pair sums), or buffers
    /// too small (as recordApply).
    std::vector<std::uint32_t> pairSumGroups() const;
    std::vector<std::uint32_t> combineGroups() const;
    void recordPairSums(vulkan::CommandSequence& sequence, const ModalKernels& kernels,
                        const vulkan::DeviceBuffer& a, IndirectArguments indirect = {}) const;
    void recordCombine(vulkan::CommandSequence& sequence, const ModalKernels& kernels,
                       const vulkan::DeviceBuffer& b, const vulkan::DeviceBuffer& out,
                       IndirectArguments indirect = {}) const;

private:
    struct Chunk {
        vulkan::DeviceBuffer values;
        std::uint32_t firstPair = 0;
        std::uint32_t pairs = 0;
    };
    struct SparseRows {
        vulkan::DeviceBuffer
            rows;  ///< per row: pair index, first texel of its slice, texels per row, 0
        vulkan::DeviceBuffer
            entries;  ///< texels of two (column, value bits) entries, slice-interleaved
        std::uint32_t rowCount = 0;
    };
    /// @throw modeflow::Error for tensor-free coefficients, which keep no `what`.
    void requireAssembled(const char* what) const;
    /// `sparse` in slices of PAIR_TILE_LANES rows (DeviceCoefficients.cpp).
    static SparseRows slicedRows(const vulkan::VulkanContext& context,
                                 const SparseCoefficients& sparse);

    int mN = 0;
    std::uint32_t mSubgroupsPerGroup = 1;
    std::uint32_t mMaxGroups = 1;
    std::vector<Chunk> mChunks;
    /// The dense advection's partial sums: rows of 8·rowOctets floats, per chunk `groups` rows
    /// of `tilesPerGroup` tiles each, from row `firstGroup`.
    struct AdvectionGroups {
        std::uint32_t firstGroup = 0, groups = 0, tilesPerGroup = 0;
    };
    struct DenseAdvection {
        vulkan::DeviceBuffer weights;  ///< one per pair
        vulkan::DeviceBuffer partial;
        std::vector<AdvectionGroups> chunks;
        std::uint32_t rows = 0;
    };
    /// The sparse entries by column i: (k, j, value bits, 0) from columnStart[i].
    struct SparseColumns {
        vulkan::DeviceBuffer start;
        vulkan::DeviceBuffer entries;
    };
    static SparseColumns sparseColumns(const vulkan::VulkanContext& context,
                                       const SparseCoefficients& sparse);
    DenseAdvection denseAdvection(const vulkan::VulkanContext& context) const;

    std::optional<SparseRows> mSparse;
    std::optional<DenseAdvection> mDenseAdvection;
    std::optional<SparseColumns> mSparseColumns;
    std::optional<TensorFreeAdvection> mTensorFree;
    std::optional<vulkan::DeviceBuffer> mPairSums;
    std::size_t mStreamedBytes = 0;
};

}  // namespace modeflow::device
