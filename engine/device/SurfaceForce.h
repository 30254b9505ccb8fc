#pragma once
/// @file SurfaceForce.h
/// Stirring on a surface, on the device (CPU reference: engine/surface/SurfaceForce.h): the
/// splats' force density at each vertex turned into its tangent plane and weighted by its area
/// (shaders/surface_splat_vertices.comp), then projected on the velocity basis as
/// f_k = Σ_v ⋆0_v g(x_v)·u_k(x_v) (shaders/surface_splat_project.comp), written where the modal
/// stepper reads its force.

#include <span>

#include "engine/format/BasisCache.h"
#include "engine/simulation/ForceSplat.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SurfaceForce {
public:
    /// Uploads the mesh's vertices, normals and areas and the modes' vertex velocities.
    /// @throw modeflow::Error when the cache is not a surface basis, or a device error.
    SurfaceForce(const vulkan::VulkanContext& context, const BasisCache& cache);

    /// Records the modal force of `splats` into the first N floats of `force` (zero for none).
    /// The splats are uploaded at once: one record per submission.
    /// @throw modeflow::Error for more than maxForceSplats splats or a radius that is not
    ///        positive.
    void record(vulkan::CommandSequence& sequence, std::span<const ForceSplat> splats,
                const vulkan::DeviceBuffer& force);

private:
    std::uint32_t mVertices, mModes;
    vulkan::ComputeKernel mVertexKernel, mProjectKernel;
    vulkan::DeviceBuffer mPoints, mNormals, mModeRows, mSplats, mVertexForce;
};

}  // namespace modeflow::device
