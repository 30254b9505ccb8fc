#pragma once
/// @file GridFrames.h
/// The frames of a grid scene's run: one OpenVDB file per frame (density, temperature, the face
/// velocity and magnetic field, the fluid mask; engine/output/VdbFrame.h), the particles' PLY
/// (engine/output/ParticleFrame.h) when the scene has any, a picture of the smoke (and the
/// particles) when asked, and the checkpoint of the simulation's state, smoke and particles.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "engine/core/MacGrid.h"
#include "engine/output/VdbFrame.h"
#include "engine/run/FramePreview.h"
#include "engine/run/FramedRun.h"
#include "engine/run/RunInputs.h"
#include "engine/simulation/Simulator.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow {

struct GridFrameFiles {
    std::filesystem::path folder;
    std::string sceneName;  ///< frames are NAME_0001.vdb, …
    std::string sceneHash;  ///< the frames' metadata
    bool halfFloat = false;
    bool previews = false;  ///< whether any frame gets a picture
    /// The device that ray-marches 3D pictures; null renders them on the CPU.
    const vulkan::VulkanContext* previewDevice = nullptr;
};

/// The VDB frame of `simulator`'s state now (the smoke and fields read from it beforehand): what
/// every grid run writes per frame, and the Python module's Simulation.write_vdb. The spans must
/// outlive the frame.
VdbFrame gridVdbFrame(const Simulator& simulator, std::span<const std::uint8_t> fluidMask,
                      const MacGrid& basisGrid, const SmokeFields& smoke,
                      std::span<const double> faceVelocity, std::span<const double> faceMagnetic,
                      int frame, std::string sceneHash, bool halfFloat);

class GridFrames final : public FramedRun {
public:
    /// `simulator` runs `run`; both must outlive this.
    GridFrames(Simulator& simulator, const RunInputs& run, GridFrameFiles files);

    const SimulationSettings& settings() const override { return mSimulator.settings(); }
    double time() const override { return mSimulator.time(); }
    FrameStats advanceFrame() override { return mSimulator.advanceFrame(); }
    std::filesystem::path frameFile(int frame) const override;
    FrameOutput readFrame(int frame, const std::filesystem::path& picture,
                          FrameProgress& bar) override;
    void restore(const Checkpoint& from) override;

private:
    Simulator& mSimulator;
    const RunInputs& mRun;
    GridFrameFiles mFiles;
    MacGrid mBasisGrid;
    std::unique_ptr<FramePreview> mPreview;
};

}  // namespace modeflow
