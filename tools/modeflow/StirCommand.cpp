#include <iostream>
#include <memory>

#include "engine/core/Error.h"
#include "engine/core/WritableDirectory.h"
#include "engine/display/Window.h"
#include "engine/run/Backend.h"
#include "engine/stir/StirApp.h"
#include "engine/stir/WindowPicture.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/compose/Preflight.h"
#include "tools/modeflow/Commands.h"
#include "tools/modeflow/NumberOptions.h"

namespace modeflow::cli {

Command addStir(CLI::App& app) {
    struct Options {
        std::string scene;
        std::optional<int> frames;
        std::optional<std::string> screenshot;
        std::optional<std::string> script;
        std::optional<std::string> cacheDir;
        std::string device = "vulkan";
        std::optional<int> width, height;
        bool offscreen = false;
        double force = stir::StirSettings{}.force;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "stir",
        "Stir a scene's smoke (a surface's dye) in a window in real time (press h in the window "
        "for the keys)");
    sub->add_option("SCENE", opts->scene, "scene file (TOML)")->required();
    sub->add_option("--frames", opts->frames,
                    "close after N frames; the clock is then the scene's frame clock "
                    "(steps_per_frame steps a frame), not the wall clock")
        ->check(countUpTo(kMaxFrames));
    sub->add_option("--screenshot", opts->screenshot, "write the last frame to this PNG file");
    sub->add_option("--script", opts->script, "replay timed mouse and key events from FILE");
    sub->add_option(
           "--width", opts->width,
           "window width in screen units (default 1280, or 960 on a CPU device such as lavapipe)")
        ->check(countUpTo(display::kMaxWindowSide));
    sub->add_option("--height", opts->height, "window height (default 720, or 540 on a CPU device)")
        ->check(countUpTo(display::kMaxWindowSide));
    sub->add_flag("--offscreen", opts->offscreen,
                  "draw into an offscreen picture instead of a window (no display needed; needs "
                  "--frames): benchmarks, scripted runs kept as a --screenshot");
    sub->add_option("--force", opts->force, "stirring acceleration per unit pointer speed (1/s)")
        ->check(finiteNonNegative());
    sub->add_option("--device", opts->device,
                    std::string(kDeviceOptionHelp) +
                        "; the window shows on the chosen Vulkan device, or with cpu on the first "
                        "suitable one");
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder");
    return [sub, opts]() {
        if (!*sub) return -1;
        // Everything that can be refused is checked before the precompute or the window.
        const Preflight checked = preflight(opts->scene, opts->device, RunParts::DynamicsAndSmoke);
        const BackendChoice& choice = checked.backend;
        const SceneSpec& scene = checked.scene;
        // The window's device opens after the precompute; a basis or a picture too large for it
        // is refused now, from the first suitable device's limits (the uploads check again).
        {
            const Backend windowDevice(BackendChoice{BackendKind::Vulkan, choice.vulkan});
            if (choice.kind == BackendKind::Vulkan) windowDevice.requireFits(scene);
            if (opts->width || opts->height)
                stir::requirePictureFits(
                    *windowDevice.vulkanContext(), opts->width.value_or(stir::kWindowWidth),
                    opts->height.value_or(stir::kWindowHeight), "--width/--height");
        }
        if (opts->screenshot) requireWritableFile(*opts->screenshot, "--screenshot");
        stir::StirOptions options;
        options.backend = choice;
        options.frames = opts->frames;
        options.width = opts->width;
        options.height = opts->height;
        options.stir.force = opts->force;
        if (opts->script) options.script = stir::readInputScript(*opts->script);
        if (opts->screenshot) options.screenshot = *opts->screenshot;
        options.offscreen = opts->offscreen;
        if (!opts->offscreen)
            display::Window::requireDisplay();
        else if (!opts->frames)
            throw Error("--offscreen needs --frames: nothing closes an offscreen stir");

        Progress progress = Progress::toStderr();
        // A surface's dye lives in its scalar basis: it has no smoke grid.
        const RunInputs run =
            prepareRun(scene, resolveCacheDir(opts->cacheDir), progress,
                       scene.isSurface() ? RunParts::Dynamics : RunParts::DynamicsAndSmoke);
        stir::runStir(options, run, std::cerr);
        return 0;
    };
}

}  // namespace modeflow::cli
