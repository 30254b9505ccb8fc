#include "engine/run/FrameLoop.h"

#include <chrono>
#include <filesystem>
#include <iostream>

#include "engine/core/Error.h"
#include "engine/core/SceneKeywords.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/run/CheckpointSchedule.h"
#include "engine/run/FramePreview.h"
#include "engine/run/FrameWriter.h"

namespace modeflow {

std::optional<Checkpoint> readResumePoint(const RunFolder& folder, bool resume,
                                          std::uint64_t runHash) {
    if (!resume || !std::filesystem::exists(folder.checkpointPath())) return std::nullopt;
    Checkpoint checkpoint = readCheckpoint(folder.checkpointPath());
    if (checkpoint.runHash != runHash)
        throw Error("checkpoint " + folder.checkpointPath().string() +
                    " was written for another scene text, basis (mesh file) or device; run "
                    "without --resume to start afresh");
    return checkpoint;
}

void runFrames(FramedRun& run, const FrameLoopOptions& o) {
    int first = 0;
    if (o.resumeFrom) {
        run.restore(*o.resumeFrom);
        first = o.resumeFrom->frame;
        std::cerr << "resuming after frame " << first << " (t = " << o.resumeFrom->time << ")\n";
    } else if (const int removed = o.folder.removeEarlierRun(); removed > 0) {
        std::cerr << "removed " << removed << " files of an earlier " << o.sceneName << " run from "
                  << o.folder.path().string() << "\n";
    }
    const auto pictureOf = [&](int frame) {
        return std::filesystem::path(run.frameFile(frame)).replace_extension(".png");
    };
    const SimulationSettings& settings = run.settings();
    FrameProgress bar(first, o.frames, settings.stepsPerFrame);
    FrameWriter writer(o.folder.checkpointPath(), bar);
    CheckpointSchedule checkpoints(o.checkpointEvery, o.frames);
    const auto begin = std::chrono::steady_clock::now();
    for (int frame = first + 1; frame <= o.frames; ++frame) {
        const std::string stage = "frame " + std::to_string(frame);
        FrameStats stats;
        try {
            stats = inRunStage(stage, o.memory, [&] {
                return bar.timed("simulating", [&] { return run.advanceFrame(); });
            });
        } catch (const ModalStateDiverged& e) {
            throw Error(divergenceAdvice(e, sceneKeyword(settings.integrator), "[simulation].dt"));
        }
        const bool picture = o.previewEvery > 0 && previewed(frame, o.frames, o.previewEvery);
        FrameOutput output = inRunStage(stage, o.memory, [&] {
            return run.readFrame(frame, picture ? pictureOf(frame) : std::filesystem::path(), bar);
        });
        output.checkpoint.runHash = o.runHash;
        const double now =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        const bool checkpoint = checkpoints.due(frame, now);
        inRunStage(stage, o.memory, [&] { writer.start(std::move(output), checkpoint); });
        // start() waited for the frame before: its checkpoint's cost is known now.
        checkpoints.written(writer.lastCheckpointSeconds());
        std::string detail;
        if (stats.unconvergedSteps)
            detail += std::to_string(stats.unconvergedSteps) + " unconverged steps ";
        if (stats.substeps > 1) detail += std::to_string(stats.substeps) + " modal substeps";
        bar.frameDone(frame, run.time(), detail);
    }
    inRunStage("frame " + std::to_string(o.frames), o.memory, [&] { writer.finish(); });
    bar.finish();
    if (o.previewEvery > 0)
        writeContactSheet(o.folder.path() / (o.sceneName + "_contact.png"), o.frames,
                          o.previewEvery, pictureOf);
}

}  // namespace modeflow
