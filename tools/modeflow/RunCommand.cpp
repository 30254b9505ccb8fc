#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/WritableDirectory.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/format/CacheFile.h"
#include "engine/output/RunFolder.h"
#include "engine/output/VdbFrame.h"
#include "engine/pipeline/Backend.h"
#include "engine/pipeline/RunInputs.h"
#include "engine/pipeline/RunMemory.h"
#include "engine/simulation/Checkpoint.h"
#include "precompute/Precompute.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/modeflow/Commands.h"
#include "tools/modeflow/FramePreview.h"
#include "tools/modeflow/FrameProgress.h"
#include "tools/modeflow/NumberOptions.h"
#include "tools/modeflow/SurfaceRun.h"

namespace modeflow::cli {
namespace {

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string hex(std::uint64_t value) {
    std::ostringstream s;
    s << std::hex << std::setw(16) << std::setfill('0') << value;
    return s.str();
}

}  // namespace

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
                  "continue an interrupted run from its last complete frame");
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
        const BackendChoice choice = parseDeviceOption(opts->device);
        const SceneSpec scene = loadScene(opts->scene);
        requireSupport(scene, choice.kind);
        const RunMemory memory = requireRunMemory(scene, choice.kind);
        // The device is opened, and what it cannot hold refused, before the output folder is made.
        std::optional<Backend> backend;
        if (!scene.isSurface()) {
            backend.emplace(choice);
            backend->requireFits(scene);
        }
        const int frames = opts->frames.value_or(scene.output.frames);
        const std::filesystem::path out = opts->out.value_or(scene.name + "_frames");
        ensureWritableDirectory(out, "output folder", "; choose another with --out");
        // One run at a time per scene in a folder; taken before any work.
        const RunFolder folder(out, scene.name);
        if (folder.staleTemporariesRemoved() > 0)
            std::cerr << "removed " << folder.staleTemporariesRemoved()
                      << " partial files of killed runs from " << out.string() << "\n";
        // The checkpoint belongs to this scene text, the basis it makes (mesh files included) and
        // the device kind; the frame count does not change results.
        const std::string sceneHash = hex(fnv1a64(fileBytes(scene.sourceFile)));
        const std::uint64_t runHash = fnv1a64(sceneHash + "|" + basisKey(scene) + "|" +
                                              std::string(capabilitiesOf(choice.kind).option));
        std::optional<Checkpoint> resumeFrom;
        if (opts->resume && std::filesystem::exists(folder.checkpointPath())) {
            resumeFrom = readCheckpoint(folder.checkpointPath());
            if (resumeFrom->runHash != runHash)
                throw Error(
                    "checkpoint " + folder.checkpointPath().string() +
                    " was written for another scene text, basis (mesh file) or device; run without "
                    "--resume to start afresh");
        }
        const bool previews = opts->preview || opts->previewEvery.has_value();
        const int previewEvery = opts->previewEvery.value_or(std::max(1, frames / 24));
        if (scene.isSurface()) {
            if (opts->half)
                throw Error("--half: surface scenes write PLY frames, in 32-bit floats");
            return runSurface({scene, frames, folder, sceneHash, runHash, resumeFrom,
                               resolveCacheDir(opts->cacheDir), memory,
                               previews ? previewEvery : 0});
        }
        std::cerr << backend->describe();

        Progress progress = Progress::toStderr();
        const RunInputs run = inRunStage(
            "preparing the run (cache, smoke mask, initial state)", memory,
            [&] { return prepareRun(scene, resolveCacheDir(opts->cacheDir), progress); });
        const SimulationSettings& settings = run.settings;
        const std::unique_ptr<Simulator> simulator = inRunStage(
            "setting up the simulation", memory, [&] { return backend->makeSimulator(run); });

        int first = 0;
        if (resumeFrom) {
            simulator->restore(resumeFrom->time, resumeFrom->velocity, resumeFrom->smoke);
            if (settings.mhd) simulator->setMagneticField(resumeFrom->magnetic);
            simulator->setCarry(resumeFrom->carry);
            first = resumeFrom->frame;
            std::cerr << "resuming after frame " << first << " (t = " << resumeFrom->time << ")\n";
        } else if (const int removed = folder.removeEarlierRun(); removed > 0) {
            std::cerr << "removed " << removed << " files of an earlier " << scene.name
                      << " run from " << out.string() << "\n";
        }

        const MacGrid basisGrid = MacGrid::fromSpec(run.cache.grid);
        const bool temperature = settings.simulatesTemperature();
        std::unique_ptr<FramePreview> preview;
        if (previews)
            preview = std::make_unique<FramePreview>(simulator->smokeGrid(), run.smokeMask,
                                                     backend->vulkanContext());
        const auto pictureOf = [&](int frame) {
            return std::filesystem::path(out / frameFileName(scene.name, frame))
                .replace_extension(".png");
        };
        FrameProgress bar(first, frames, settings.stepsPerFrame);
        for (int frame = first + 1; frame <= frames; ++frame) {
            const std::string stage = "frame " + std::to_string(frame);
            FrameStats stats;
            try {
                stats = inRunStage(stage, memory, [&] {
                    return bar.timed("simulating", [&] { return simulator->advanceFrame(); });
                });
            } catch (const ModalStateDiverged& e) {
                throw Error(
                    divergenceAdvice(e, sceneKeyword(settings.integrator), "[simulation].dt"));
            }
            const SmokeFields smoke = inRunStage(stage, memory, [&] {
                return bar.timed("reading fields", [&] { return simulator->smoke(); });
            });
            const std::vector<double> faceVelocity =
                bar.timed("reading fields", [&] { return simulator->faceVelocity(); });
            const std::vector<double> faceMagnetic =
                bar.timed("reading fields", [&] { return simulator->faceMagneticField(); });
            VdbFrame vdb;
            vdb.smokeGrid = simulator->smokeGrid();
            vdb.basisGrid = basisGrid;
            vdb.density = std::span<const double>(smoke.density);
            if (temperature) vdb.temperature = std::span<const double>(smoke.temperature);
            vdb.faceVelocity = faceVelocity;
            vdb.faceMagnetic = faceMagnetic;
            vdb.fluidMask = run.smokeMask;
            vdb.frame = frame;
            vdb.time = simulator->time();
            vdb.sceneHash = sceneHash;
            vdb.modeflowVersion = MODEFLOW_VERSION;
            vdb.options.halfFloat = opts->half;
            inRunStage(stage, memory, [&] {
                bar.timed("VDB files",
                          [&] { writeVdbFrame(out / frameFileName(scene.name, frame), vdb); });
            });
            if (preview && previewed(frame, frames, previewEvery))
                bar.timed("previews",
                          [&] { preview->write(pictureOf(frame), smoke, temperature); });
            bar.timed("checkpoint", [&] {
                writeCheckpoint(folder.checkpointPath(),
                                {frame, simulator->time(), runHash, simulator->velocity(),
                                 simulator->magneticField(), simulator->carry(), smoke});
            });
            std::string detail;
            if (stats.unconvergedSteps)
                detail += std::to_string(stats.unconvergedSteps) + " unconverged steps ";
            if (stats.substeps > 1) detail += std::to_string(stats.substeps) + " modal substeps";
            bar.frameDone(frame, simulator->time(), detail);
        }
        bar.finish();
        if (preview)
            writeContactSheet(out / (scene.name + "_contact.png"), frames, previewEvery, pictureOf);
        backend->requireCleanValidation();
        std::printf("%s\n", out.string().c_str());
        return 0;
    };
}

}  // namespace modeflow::cli
