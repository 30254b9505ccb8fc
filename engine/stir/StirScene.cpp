/// @file StirScene.cpp

#include "engine/stir/StirScene.h"

#include "engine/run/Backend.h"
#include "engine/run/RunInputs.h"
#include "engine/stir/GridStirScene.h"
#include "engine/stir/SurfaceStirScene.h"

namespace modeflow::stir {

std::unique_ptr<StirScene> makeStirScene(const Backend& backend, const RunInputs& run,
                                         const StirSettings& settings,
                                         const vulkan::VulkanContext& context) {
    if (run.cache.kind == BasisKind::Surface)
        return std::make_unique<SurfaceStirScene>(backend, run, settings, context);
    return std::make_unique<GridStirScene>(backend, run, settings, context);
}

}  // namespace modeflow::stir
