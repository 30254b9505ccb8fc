#include "engine/run/SurfaceFrames.h"

#include <utility>
#include <vector>

#include "engine/output/PlyFrame.h"
#include "engine/preview/PngWriter.h"
#include "engine/preview/SurfaceImage.h"

namespace modeflow {

SurfaceFrames::SurfaceFrames(SurfaceSimulator& simulator, const RunInputs& run,
                             std::filesystem::path folder, std::string sceneName,
                             std::string sceneHash)
    : mSimulation(simulator),
      mRun(run),
      mFolder(std::move(folder)),
      mSceneName(std::move(sceneName)),
      mSceneHash(std::move(sceneHash)),
      mDyeScale(dyeColourScale(run.settings)) {}

FrameStats SurfaceFrames::advanceFrame() {
    return mSimulation.advanceSteps(mRun.settings.stepsPerFrame);
}

std::filesystem::path SurfaceFrames::frameFile(int frame) const {
    return mFolder / plyFrameFileName(mSceneName, frame);
}

FrameOutput SurfaceFrames::readFrame(int frame, const std::filesystem::path& picture,
                                     FrameProgress& bar) {
    FrameOutput out;
    const Eigen::VectorXd modalDye = mSimulation.dye(), modalVelocity = mSimulation.velocity();
    std::vector<double> dye =
        bar.timed("reading fields", [&] { return surfaceDyeAtVertices(mRun.cache, modalDye); });
    std::vector<double> velocity = bar.timed(
        "reading fields", [&] { return surfaceVelocityAtVertices(mRun.cache, modalVelocity); });
    out.checkpoint = {frame, mSimulation.time(), 0, modalVelocity, {}, mSimulation.carry(), {}, {}};
    out.checkpoint.smoke.density.assign(modalDye.data(), modalDye.data() + modalDye.size());
    out.checkpoint.smoke.temperature.assign(modalDye.size(), 0.0);  // dye has none
    out.writeFiles = [this, dye = std::move(dye), velocity = std::move(velocity), picture,
                      file = frameFile(frame)](const Checkpoint& state, FrameProgress& bar) {
        PlyFrame ply;
        ply.mesh = &mRun.cache.surface.mesh;  // the run's, never changed while it runs
        ply.dye = dye;
        ply.velocity = velocity;
        ply.dyeScale = mDyeScale;
        ply.frame = state.frame;
        ply.time = state.time;
        ply.sceneHash = mSceneHash;
        bar.timed("PLY files", [&] { writePlyFrame(file, ply); });
        if (!picture.empty())
            bar.timed("previews", [&] {
                preview::writePng(picture, preview::surfaceImage(mRun.cache.surface.mesh, dye,
                                                                 mDyeScale, 512, 384));
            });
    };
    return out;
}

void SurfaceFrames::restore(const Checkpoint& from) {
    mSimulation.restore(from.time, from.velocity,
                        Eigen::Map<const Eigen::VectorXd>(from.smoke.density.data(),
                                                          Eigen::Index(from.smoke.density.size())));
    mSimulation.setCarry(from.carry);
}

}  // namespace modeflow
