#pragma once
/// @file SurfaceFrames.h
/// The frames of a surface scene's run (scenes/README.md, "Curved surfaces"): the simulation of
/// the flow and its dye on either backend (SurfaceSimulator), one PLY file per frame
/// (engine/output/PlyFrame.h), a picture of the dye when asked, and the checkpoint (the dye's modal
/// state [mean, f] in its density, zeros in its temperature).

#include <filesystem>
#include <memory>
#include <string>

#include "engine/run/FramedRun.h"
#include "engine/run/RunInputs.h"
#include "engine/simulation/SurfaceSimulator.h"

namespace modeflow {

class SurfaceFrames final : public FramedRun {
public:
    /// Advances `simulator` of `run` (both must outlive this) from its initial state; frames are
    /// `folder`/NAME_0001.ply, … with `sceneHash` in their header.
    SurfaceFrames(SurfaceSimulator& simulator, const RunInputs& run, std::filesystem::path folder,
                  std::string sceneName, std::string sceneHash);

    const SimulationSettings& settings() const override { return mRun.settings; }
    double time() const override { return mSimulation.time(); }
    FrameStats advanceFrame() override;
    std::filesystem::path frameFile(int frame) const override;
    FrameOutput readFrame(int frame, const std::filesystem::path& picture,
                          FrameProgress& bar) override;
    void restore(const Checkpoint& from) override;

private:
    SurfaceSimulator& mSimulation;
    const RunInputs& mRun;
    std::filesystem::path mFolder;
    std::string mSceneName, mSceneHash;
    double mDyeScale;
};

}  // namespace modeflow
