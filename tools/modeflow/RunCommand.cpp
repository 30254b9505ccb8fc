#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

#include "engine/dynamics/CachedCoefficients.h"
#include "engine/format/CacheFile.h"
#include "engine/format/Error.h"
#include "engine/format/WritableDirectory.h"
#include "engine/output/VdbFrame.h"
#include "engine/simulation/Checkpoint.h"
#include "engine/simulation/ReferenceSimulation.h"
#include "engine/simulation/Simulation.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/FluidMask.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/modeflow/Commands.h"
#include "tools/modeflow/DeviceOption.h"
#include "tools/modeflow/FramePreview.h"
#include "tools/modeflow/FrameProgress.h"
#include "tools/modeflow/InitialState.h"
#include "tools/modeflow/NumberOptions.h"

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

/// Whether the scene simulates temperature (a source heats, or buoyancy reads it).
bool simulatesTemperature(const SceneSpec& scene) {
    if (scene.smoke.buoyancy != 0.0) return true;
    for (const SourceSpec& source : scene.sources)
        if (source.temperature != 0.0) return true;
    return false;
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
    CLI::App* sub = app.add_subcommand("run", "Simulate a scene and write one OpenVDB file per frame");
    sub->add_option("SCENE", opts->scene, "scene file (TOML)")->required();
    sub->add_option("--frames", opts->frames, "frames to write (default: [output].frames)")
        ->check(countUpTo(kMaxFrames));
    sub->add_option("--out", opts->out, "output folder (default: NAME_frames beside the current folder)");
    sub->add_option("--device", opts->device, kDeviceHelp);
    sub->add_flag("--resume", opts->resume, "continue an interrupted run from its last complete frame");
    sub->add_flag("--half", opts->half, "store VDB values as 16-bit floats");
    sub->add_flag("--preview", opts->preview,
                  "also write PNG pictures (NAME_0001.png; 3D scenes ray-marched) and a contact sheet");
    sub->add_option("--preview-every", opts->previewEvery,
                    "picture every K frames (default: about 24 pictures per run); implies --preview")
        ->check(countUpTo(kMaxFrames));
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder");
    return [sub, opts]() {
        if (!*sub) return -1;
        // Everything that can be refused is checked before any precompute or simulation work.
        const auto deviceOptions = parseDevice(opts->device);
        const SceneSpec scene = loadScene(opts->scene);
        const Runtime runtime = deviceOptions ? Runtime::Device : Runtime::CpuReference;
        requireRuntimeSupport(scene, runtime);
        const int frames = opts->frames.value_or(scene.output.frames);
        const std::filesystem::path out = opts->out.value_or(scene.name + "_frames");
        ensureWritableDirectory(out, "output folder", "; choose another with --out");
        const std::filesystem::path checkpointPath = out / (scene.name + ".resume");
        // The checkpoint belongs to this scene text and device kind; frames do not change results.
        const std::string sceneHash = hex(fnv1a64(fileBytes(scene.sourceFile)));
        const std::uint64_t runHash = fnv1a64(sceneHash + "|" + (deviceOptions ? "vulkan" : "cpu"));

        Progress progress = Progress::toStderr();
        const auto cachePath = ensureCache(scene, resolveCacheDir(opts->cacheDir), false, progress).path;
        const BasisCache cache = readCache(cachePath);
        const auto coefficients = coefficientsFromCache(cache);
        const SimulationSettings settings = SimulationSettings::fromScene(scene, cache, runtime);
        const std::vector<std::uint8_t> mask = fluidMask(scene, cache, settings.smokeScale);

        std::unique_ptr<vulkan::VulkanContext> context;
        std::unique_ptr<Simulator> simulator;
        if (deviceOptions) {
            context = std::make_unique<vulkan::VulkanContext>(*deviceOptions);
            std::cerr << context->describe();
            simulator = std::make_unique<Simulation>(*context, cache, *coefficients, settings, mask);
        } else {
            simulator = std::make_unique<ReferenceSimulation>(cache, *coefficients, settings, mask);
        }

        int first = 0;
        if (opts->resume && std::filesystem::exists(checkpointPath)) {
            const Checkpoint checkpoint = readCheckpoint(checkpointPath);
            if (checkpoint.runHash != runHash)
                throw Error("checkpoint " + checkpointPath.string() +
                            " was written for another scene text or device; run without --resume to start afresh");
            simulator->restore(checkpoint.time, checkpoint.velocity, checkpoint.smoke);
            if (settings.mhd) simulator->setMagneticField(checkpoint.magnetic);
            first = checkpoint.frame;
            std::cerr << "resuming after frame " << first << " (t = " << checkpoint.time << ")\n";
        } else {
            simulator->setVelocity(initialVelocity(scene, cache, coefficients->size()));
            if (settings.mhd) simulator->setMagneticField(initialMagneticField(scene, cache, coefficients->size()));
        }

        const MacGrid basisGrid = MacGrid::fromSpec(cache.grid);
        const bool temperature = simulatesTemperature(scene);
        const bool previews = opts->preview || opts->previewEvery.has_value();
        const int previewEvery = opts->previewEvery.value_or(std::max(1, frames / 24));
        std::unique_ptr<FramePreview> preview;
        if (previews) preview = std::make_unique<FramePreview>(simulator->smokeGrid(), mask, context.get());
        FrameProgress bar(first, frames, settings.stepsPerFrame);
        for (int frame = first + 1; frame <= frames; ++frame) {
            const FrameStats stats = simulator->advanceFrame();
            const SmokeFields smoke = simulator->smoke();
            const std::vector<double> faceVelocity = simulator->faceVelocity();
            const std::vector<double> faceMagnetic = simulator->faceMagneticField();
            VdbFrame vdb;
            vdb.smokeGrid = simulator->smokeGrid();
            vdb.basisGrid = basisGrid;
            vdb.density = std::span<const double>(smoke.density);
            if (temperature) vdb.temperature = std::span<const double>(smoke.temperature);
            vdb.faceVelocity = faceVelocity;
            vdb.faceMagnetic = faceMagnetic;
            vdb.fluidMask = mask;
            vdb.frame = frame;
            vdb.time = simulator->time();
            vdb.sceneHash = sceneHash;
            vdb.modeflowVersion = MODEFLOW_VERSION;
            vdb.options.halfFloat = opts->half;
            writeVdbFrame(out / frameFileName(scene.name, frame), vdb);
            if (preview && (frame % previewEvery == 0 || frame == frames)) {
                std::filesystem::path png = out / frameFileName(scene.name, frame);
                preview->write(png.replace_extension(".png"), frame, smoke, temperature);
            }
            writeCheckpoint(checkpointPath, {frame, simulator->time(), runHash, simulator->velocity(),
                                             simulator->magneticField(), smoke});
            std::string detail;
            if (stats.unconvergedSteps) detail += std::to_string(stats.unconvergedSteps) + " unconverged steps ";
            if (stats.substeps > 1) detail += std::to_string(stats.substeps) + " modal substeps";
            bar.frameDone(frame, simulator->time(), detail);
        }
        bar.finish();
        if (preview) preview->writeContactSheet(out / (scene.name + "_contact.png"));
        if (context && context->validationMessageCount() > 0)
            throw Error("the Vulkan validation layer reported " + std::to_string(context->validationMessageCount()) +
                        " problems; the first: " + context->validationMessages().front());
        std::printf("%s\n", out.string().c_str());
        return 0;
    };
}

}  // namespace modeflow::cli
