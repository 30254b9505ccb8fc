#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/WritableDirectory.h"
#include "engine/output/RunFolder.h"
#include "engine/run/Backend.h"
#include "engine/run/FrameLoop.h"
#include "engine/run/GridFrames.h"
#include "engine/run/SurfaceFrames.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/compose/Preflight.h"
#include "tools/compose/RunIdentity.h"
#include "tools/modeflow/Commands.h"
#include "tools/modeflow/NumberOptions.h"

namespace modeflow::cli {

Command addRun(CLI::App& app) {
    struct Options {
        std::string scene;
        std::optional<int> frames;
        std::optional<std::string> out;
        std::optional<std::string> cacheDir;
        std::string device = "vulkan";
        bool resume = false;
        bool half = false;
        bool preview = false;
        std::optional<int> previewEvery;
        std::optional<int> checkpointEvery;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* sub =
        app.add_subcommand("run", "Simulate a scene and write one OpenVDB file per frame");
    sub->add_option("SCENE", opts->scene, "scene file (TOML)")->required();
    sub->add_option("--frames", opts->frames, "frames to write (default: [output].frames)")
        ->check(countUpTo(kMaxFrames));
    sub->add_option("--out", opts->out,
                    "output folder (default: NAME_frames beside the current folder)");
    sub->add_option("--device", opts->device, kDeviceOptionHelp);
    sub->add_flag("--resume", opts->resume,
                  "continue an interrupted run from its last checkpoint (the frames after it are "
                  "written again, the same to the bit)");
    sub->add_option("--checkpoint-every", opts->checkpointEvery,
                    "write the resume checkpoint every K frames and after the last (default: as "
                    "often as keeps it under 5% of the run's time)")
        ->check(countUpTo(kMaxFrames));
    sub->add_flag("--half", opts->half, "store VDB values as 16-bit floats");
    sub->add_flag(
        "--preview", opts->preview,
        "also write PNG pictures (NAME_0001.png; 3D scenes ray-marched) and a contact sheet");
    sub->add_option(
           "--preview-every", opts->previewEvery,
           "picture every K frames (default: about 24 pictures per run); implies --preview")
        ->check(countUpTo(kMaxFrames));
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder");
    return [sub, opts]() {
        if (!*sub) return -1;
        // Everything that can be refused is checked before any precompute or simulation work.
        const Preflight checked = preflight(opts->scene, opts->device, RunParts::DynamicsAndSmoke);
        const SceneSpec& scene = checked.scene;
        // The device is opened, and what it cannot hold refused, before the output folder is made.
        if (scene.isSurface() && opts->half)
            throw Error("--half: surface scenes write PLY frames, in 32-bit floats");
        const Backend backend(checked.backend);
        backend.requireFits(scene);
        const int frames = opts->frames.value_or(scene.output.frames);
        // The run's length as --frames sets it: a deforming obstacle's files are read (and a
        // missing one refused) as far as the run goes.
        SceneSpec shot = scene;
        shot.output.frames = frames;
        const std::filesystem::path out = opts->out.value_or(scene.name + "_frames");
        ensureWritableDirectory(out, "output folder", "; choose another with --out");
        // One run at a time per scene in a folder; taken before any work.
        const RunFolder folder(out, scene.name);
        if (folder.staleTemporariesRemoved() > 0)
            std::cerr << "removed " << folder.staleTemporariesRemoved()
                      << " partial files of killed runs from " << out.string() << "\n";
        const RunIdentity id = runIdentity(scene, checked.backend.kind);
        const bool previews = opts->preview || opts->previewEvery.has_value();
        const FrameLoopOptions loop{
            folder,
            scene.name,
            frames,
            id.runHash,
            readResumePoint(folder, opts->resume, id.runHash),
            previews ? opts->previewEvery.value_or(std::max(1, frames / 24)) : 0,
            checked.memory,
            opts->checkpointEvery};
        std::cerr << backend.describe();

        Progress progress = Progress::toStderr();
        const RunInputs run =
            inRunStage(scene.isSurface() ? "preparing the run (cache, initial state)"
                                         : "preparing the run (cache, smoke mask, initial state)",
                       checked.memory, [&] {
                           return prepareRun(
                               shot, resolveCacheDir(opts->cacheDir), progress,
                               scene.isSurface() ? RunParts::Dynamics : RunParts::DynamicsAndSmoke);
                       });
        if (scene.isSurface()) {
            const std::unique_ptr<SurfaceSimulator> simulator =
                inRunStage("setting up the simulation", checked.memory,
                           [&] { return backend.makeSurfaceSimulator(run); });
            SurfaceFrames surface(*simulator, run, out, scene.name, id.sceneHash);
            runFrames(surface, loop);
        } else {
            const std::unique_ptr<Simulator> simulator =
                inRunStage("setting up the simulation", checked.memory,
                           [&] { return backend.makeSimulator(run); });
            GridFrames grid(
                *simulator, run,
                {out, scene.name, id.sceneHash, opts->half, previews, backend.vulkanContext()});
            runFrames(grid, loop);
        }
        backend.requireCleanValidation();
        std::printf("%s\n", out.string().c_str());
        return 0;
    };
}

}  // namespace modeflow::cli
