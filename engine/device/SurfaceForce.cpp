#include "engine/device/SurfaceForce.h"

#include <array>
// The generated headers use uint32_t without including <cstdint>.
#include <cstdint>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/VertexNormals.h"
#include "engine/device/SplatRecords.h"
#include "engine/vulkan/CommandSequence.h"
#include "shaders/SurfaceForceParams.h"
#include "shaders/surface_splat_project.spv.h"
#include "shaders/surface_splat_vertices.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroup = 64;

const BasisCache& surfaceOf(const BasisCache& cache) {
    if (cache.kind != BasisKind::Surface)
        throw Error("surface force: the basis is not a surface's");
    return cache;
}

/// x, y, z and w per vertex.
std::vector<float> vertexQuads(const std::vector<Vec3>& xyz, const Eigen::VectorXd* w) {
    std::vector<float> quads(4 * xyz.size(), 0.0f);
    for (std::size_t v = 0; v < xyz.size(); ++v) {
        for (int k = 0; k < 3; ++k) quads[4 * v + std::size_t(k)] = float(xyz[v][k]);
        if (w) quads[4 * v + 3] = float((*w)[Eigen::Index(v)]);
    }
    return quads;
}

/// Mode k's velocity at every vertex, row k: vertexVelocity transposed.
std::vector<float> modeRows(const Eigen::MatrixXd& vertexVelocity) {
    const Eigen::MatrixXf rows = vertexVelocity.cast<float>();  // column k: mode k
    return {rows.data(), rows.data() + rows.size()};
}

}  // namespace

SurfaceForce::SurfaceForce(const vulkan::VulkanContext& context, const BasisCache& cache)
    : mVertices(std::uint32_t(surfaceOf(cache).surface.mesh.vertices.size())),
      mModes(std::uint32_t(cache.surface.vertexVelocity.cols())),
      mVertexKernel(context, {"surface_splat_vertices", surface_splat_vertices_spv, 4,
                              sizeof(shaders::SurfaceSplatParams), kWorkgroup}),
      mProjectKernel(context, {"surface_splat_project", surface_splat_project_spv, 3,
                               sizeof(shaders::SurfaceSplatParams), kWorkgroup}),
      mPoints(vulkan::DeviceBuffer::fromValues<float>(
          context, vertexQuads(cache.surface.mesh.vertices, &cache.scalar.cellStar),
          "surface vertices")),
      mNormals(vulkan::DeviceBuffer::fromValues<float>(
          context, vertexQuads(vertexNormals(cache.surface.mesh), nullptr), "surface normals")),
      mModeRows(vulkan::DeviceBuffer::fromValues<float>(
          context, modeRows(cache.surface.vertexVelocity), "surface mode velocities")),
      mSplats(context, maxForceSplats * sizeof(shaders::ForceSplatRecord), "surface splats"),
      mVertexForce(context, 3 * std::size_t(mVertices) * sizeof(float), "surface vertex force") {}

void SurfaceForce::record(vulkan::CommandSequence& sequence, std::span<const ForceSplat> splats,
                          const vulkan::DeviceBuffer& force) {
    const std::vector<shaders::ForceSplatRecord> records =
        splatRecords(splats, maxForceSplats, "surface force");
    if (records.empty()) {
        sequence.fill(force, VkDeviceSize(mModes) * sizeof(float), 0);
        return;
    }
    mSplats.upload<shaders::ForceSplatRecord>(records);
    const shaders::SurfaceSplatParams params{mVertices, std::uint32_t(records.size()), mModes,
                                             3 * mVertices};
    const std::array<const vulkan::DeviceBuffer*, 4> atVertices{&mPoints, &mNormals, &mSplats,
                                                                &mVertexForce};
    sequence.dispatch(mVertexKernel, atVertices, params, (mVertices + kWorkgroup - 1) / kWorkgroup);
    const std::array<const vulkan::DeviceBuffer*, 3> projection{&mModeRows, &mVertexForce, &force};
    sequence.dispatch(mProjectKernel, projection, params, (mModes + kWorkgroup - 1) / kWorkgroup);
}

}  // namespace modeflow::device
