#include "engine/device/ParticleAdvection.h"

#include <algorithm>
#include <cstring>

#include "engine/core/FaceLocation.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/device/ObstacleRecords.h"
#include "engine/device/SmokeState.h"
#include "engine/simulation/ParticleMotion.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ParticleStepParams.h"
#include "shaders/particle_step_2d.spv.h"
#include "shaders/particle_step_3d.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroupSize = 64;

/// Bytes of `count` 32-bit words (at least one).
std::size_t wordBytes(std::int64_t count) {
    return std::size_t(std::max<std::int64_t>(count, 1)) * sizeof(std::uint32_t);
}

/// Bytes of `count` vec4s (at least one).
std::size_t vec4Bytes(std::int64_t count) {
    return std::size_t(std::max<std::int64_t>(count, 1)) * 4 * sizeof(float);
}

/// Positions (xyz, the set's bits in w) and velocities as the kernel holds them.
void packed(const Particles& particles, std::vector<float>& positions,
            std::vector<float>& velocities) {
    positions.resize(4 * particles.size());
    velocities.resize(4 * particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        for (int a = 0; a < 3; ++a) {
            positions[4 * i + a] = float(particles.position[3 * i + a]);
            velocities[4 * i + a] = float(particles.velocity[3 * i + a]);
        }
        const std::uint32_t set = particles.set[i];
        std::memcpy(&positions[4 * i + 3], &set, sizeof set);
        velocities[4 * i + 3] = 0.0f;
    }
}

}  // namespace

ParticleAdvection::ParticleAdvection(const vulkan::VulkanContext& context, const SmokeState& state,
                                     std::span<const std::uint8_t> fluidMask,
                                     std::vector<ParticleSetSpec> sets, double shotEnd)
    : mContext(context),
      mEmission(std::move(sets), shotEnd),
      mPositions(context, vec4Bytes(mEmission.capacity()), "particle positions"),
      mVelocities(context, vec4Bytes(mEmission.capacity()), "particle velocities"),
      mSets(context,
            std::max<std::size_t>(mEmission.sets().size(), 1) * sizeof(shaders::ParticleSetRecord),
            "particle sets"),
      mPoses(context, std::size_t(maxObstacles) * sizeof(shaders::ObstacleRecord),
             "particle solids"),
      mWork(context, 8 * sizeof(std::uint32_t), "particles near solids: work"),
      mNear(context, wordBytes(mEmission.capacity()), "particles near solids"),
      mStarts(context, vec4Bytes(mEmission.capacity()), "particles near solids: starts"),
      mInside(context, wordBytes(mEmission.capacity()), "particles in solids"),
      mLattices(context) {
    if (empty()) return;
    mMask.assign(fluidMask.begin(), fluidMask.end());
    const bool flat = state.smokeGrid().dim == 2;
    mKernel.emplace(context, vulkan::ComputeKernelSpec{
                                 flat ? "particle_step_2d" : "particle_step_3d",
                                 flat ? std::span<const std::uint32_t>(particle_step_2d_spv)
                                      : std::span<const std::uint32_t>(particle_step_3d_spv),
                                 11,
                                 sizeof(shaders::ParticleStepParams),
                                 kWorkgroupSize,
                                 // Records as texels, lattices and mask as values, the
                                 // velocity's pairs as words: shaders/ObstacleShape.glsl.
                                 {},
                                 {0},
                                 {3},
                                 {1, 2}});
}

void ParticleAdvection::record(vulkan::CommandSequence& sequence, const SmokeState& state,
                               std::span<const MovingObstacle> solids, double t, double dt) {
    if (empty()) return;
    const MacGrid& smoke = state.smokeGrid();
    Particles fresh;
    if (mEmission.emit(t + dt, smoke, mMask, fresh) > 0) {
        std::vector<float> positions, velocities;
        packed(fresh, positions, velocities);
        mPositions.upload<float>(positions, VkDeviceSize(mCount) * 4 * sizeof(float));
        mVelocities.upload<float>(velocities, VkDeviceSize(mCount) * 4 * sizeof(float));
        mCount += std::uint32_t(fresh.size());
    }
    if (mCount == 0) return;
    if (dt != mSetsDt) {
        std::vector<shaders::ParticleSetRecord> records;
        for (const ParticleSetSpec& set : mEmission.sets()) {
            const ParticleResponse r = particleResponse(set, dt);
            records.push_back(
                {r.inertial ? 1u : 0u, float(r.decay), float(r.reach), float(r.fall)});
        }
        mSets.upload<shaders::ParticleSetRecord>(records);
        mSetsDt = dt;
    }
    requireLevelSets(solids);
    mLattices.update(solids);
    std::vector<shaders::ObstacleRecord> poses;
    for (const MovingObstacle& solid : solids)
        poses.push_back(obstacleRecord(solid, solid.poseAt(t + dt), mLattices));
    if (!poses.empty()) mPoses.upload<shaders::ObstacleRecord>(poses);

    const MacGrid& basis = state.basisGrid();
    shaders::ParticleStepParams params{};
    params.count = mCount;
    params.obstacleCount = std::uint32_t(solids.size());
    params.boundary = basis.boundaryBits();
    params.openSides = basis.crossableSideBits();
    params.allFluid = state.fluidCellCount() == std::uint32_t(smoke.cellCount()) ? 1u : 0u;
    params.up = std::uint32_t(upAxis(basis));
    params.dt = float(dt);
    params.margin = float(particleExitMargin(smoke));
    for (int a = 0; a < 3; ++a) {
        params.cells[a] = std::uint32_t(basis.cells[a]);
        params.faceStart[a] = a < basis.dim ? std::uint32_t(basis.faceOffset(a)) : 0u;
        params.origin[a] = float(basis.origin[a]);
        params.spacing[a] = float(basis.spacing[a]);
        params.smokeCells[a] = std::uint32_t(smoke.cells[a]);
        params.smokeSpacing[a] = float(smoke.spacing[a]);
    }
    // Bindings 0-10 of shaders/ParticleStep.glsl.
    const std::array<const vulkan::DeviceBuffer*, 11> buffers{&mPoses,       &mLattices.buffer(),
                                                              &state.mask(), &state.facePairs(),
                                                              &mPositions,   &mVelocities,
                                                              &mSets,        &mWork,
                                                              &mNear,        &mStarts,
                                                              &mInside};
    const std::uint32_t maxGroups = mContext.properties().limits.maxComputeWorkGroupCount[0];
    params.maxGroups = maxGroups;
    const std::uint32_t perDispatch = maxGroups * kWorkgroupSize;
    const std::uint32_t kinds = solidKinds(solids);
    if (!solids.empty()) sequence.fill(mWork, mWork.bytes(), 0u);
    for (std::uint32_t first = 0; first < mCount; first += perDispatch) {
        params.first = first;
        const std::uint32_t chunk = std::min(perDispatch, mCount - first);
        sequence.dispatch(mKernel->with({kinds, PARTICLE_STEP_MOVE}), buffers, params,
                          (chunk + kWorkgroupSize - 1) / kWorkgroupSize);
    }
    if (solids.empty()) return;
    const vulkan::ComputeKernel& arguments = mKernel->with({kinds, PARTICLE_STEP_ARGS});
    sequence.dispatch(arguments, buffers, params, 1);
    sequence.dispatchIndirect(mKernel->with({kinds, PARTICLE_STEP_NEAR}), buffers, params, mWork,
                              0);
    sequence.dispatch(arguments, buffers, params, 1);
    sequence.dispatchIndirect(mKernel->with({kinds, PARTICLE_STEP_INSIDE}), buffers, params, mWork,
                              4 * sizeof(std::uint32_t));
}

Particles ParticleAdvection::particles() const {
    Particles out;
    if (mCount == 0) return out;
    std::vector<float> positions(4 * std::size_t(mCount)), velocities(positions.size());
    mPositions.download<float>(positions);
    mVelocities.download<float>(velocities);
    out.position.resize(3 * std::size_t(mCount));
    out.velocity.resize(out.position.size());
    out.set.resize(mCount);
    for (std::size_t i = 0; i < mCount; ++i) {
        for (int a = 0; a < 3; ++a) {
            out.position[3 * i + a] = positions[4 * i + a];
            out.velocity[3 * i + a] = velocities[4 * i + a];
        }
        std::uint32_t set;
        std::memcpy(&set, &positions[4 * i + 3], sizeof set);
        out.set[i] = std::uint8_t(set);
    }
    return out;
}

void ParticleAdvection::restore(const Particles& particles) {
    mEmission.restore(particles);
    std::vector<float> positions, velocities;
    packed(particles, positions, velocities);
    if (!positions.empty()) {
        mPositions.upload<float>(positions);
        mVelocities.upload<float>(velocities);
    }
    mCount = std::uint32_t(particles.size());
}

}  // namespace modeflow::device
