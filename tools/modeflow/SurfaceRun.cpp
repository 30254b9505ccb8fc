/// @file SurfaceRun.cpp

#include "tools/modeflow/SurfaceRun.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "engine/core/SceneKeywords.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/output/PlyFrame.h"
#include "engine/pipeline/RunInputs.h"
#include "engine/preview/PngWriter.h"
#include "engine/preview/SurfaceImage.h"
#include "engine/surface/SurfaceSimulation.h"
#include "tools/modeflow/FramePreview.h"
#include "tools/modeflow/FrameProgress.h"

namespace modeflow::cli {

int runSurface(const SurfaceRunOptions& o) {
    Progress progress = Progress::toStderr();
    const RunInputs run = inRunStage("preparing the run (cache, initial state)", o.memory, [&] {
        return prepareRun(o.scene, o.cacheDir, progress, RunParts::Dynamics);
    });
    SurfaceSimulation simulation(run.cache, *run.coefficients, run.settings, run.initialVelocity);
    int first = 0;
    if (o.resumeFrom) {
        simulation.restore(
            o.resumeFrom->time, o.resumeFrom->velocity,
            Eigen::Map<const Eigen::VectorXd>(o.resumeFrom->smoke.density.data(),
                                              Eigen::Index(o.resumeFrom->smoke.density.size())));
        simulation.setCarry(o.resumeFrom->carry);
        first = o.resumeFrom->frame;
        std::cerr << "resuming after frame " << first << " (t = " << o.resumeFrom->time << ")\n";
    } else if (const int removed = o.folder.removeEarlierRun(); removed > 0) {
        std::cerr << "removed " << removed << " files of an earlier " << o.scene.name
                  << " run from " << o.folder.path().string() << "\n";
    }
    const double dyeScale = dyeColourScale(run.settings);

    const auto pictureOf = [&](int frame) {
        return std::filesystem::path(o.folder.path() / plyFrameFileName(o.scene.name, frame))
            .replace_extension(".png");
    };
    FrameProgress bar(first, o.frames, run.settings.stepsPerFrame);
    for (int frame = first + 1; frame <= o.frames; ++frame) {
        const std::string stage = "frame " + std::to_string(frame);
        try {
            inRunStage(stage, o.memory,
                       [&] { bar.timed("simulating", [&] { simulation.advanceFrame(); }); });
        } catch (const ModalStateDiverged& e) {
            throw Error(
                divergenceAdvice(e, sceneKeyword(run.settings.integrator), "[simulation].dt"));
        }
        const std::vector<double> dye =
            bar.timed("reading fields", [&] { return simulation.dye().vertexValues(); });
        const std::vector<double> velocity =
            bar.timed("reading fields", [&] { return simulation.vertexVelocity(); });
        PlyFrame ply;
        ply.mesh = &run.cache.surface.mesh;
        ply.dye = dye;
        ply.velocity = velocity;
        ply.dyeScale = dyeScale;
        ply.frame = frame;
        ply.time = simulation.time();
        ply.sceneHash = o.sceneHash;
        inRunStage(stage, o.memory, [&] {
            bar.timed("PLY files", [&] {
                writePlyFrame(o.folder.path() / plyFrameFileName(o.scene.name, frame), ply);
            });
        });
        if (o.previewEvery > 0 && previewed(frame, o.frames, o.previewEvery))
            bar.timed("previews", [&] {
                preview::writePng(pictureOf(frame), preview::surfaceImage(run.cache.surface.mesh,
                                                                          dye, dyeScale, 512, 384));
            });
        Checkpoint checkpoint{frame, simulation.time(),  o.runHash, simulation.velocity(),
                              {},    simulation.carry(), {}};
        const Eigen::VectorXd& state = simulation.dye().state();
        checkpoint.smoke.density.assign(state.data(), state.data() + state.size());
        checkpoint.smoke.temperature.assign(checkpoint.smoke.density.size(), 0.0);  // dye has none
        bar.timed("checkpoint", [&] { writeCheckpoint(o.folder.checkpointPath(), checkpoint); });
        bar.frameDone(frame, simulation.time(), "");
    }
    bar.finish();
    if (o.previewEvery > 0)
        writeContactSheet(o.folder.path() / (o.scene.name + "_contact.png"), o.frames,
                          o.previewEvery, pictureOf);
    std::printf("%s\n", o.folder.path().string().c_str());
    return 0;
}

}  // namespace modeflow::cli
