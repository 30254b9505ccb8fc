/// @file GridStirScene.cpp

#include "engine/stir/GridStirScene.h"

namespace modeflow::stir {

GridStirScene::GridStirScene(const Backend& backend, const RunInputs& run,
                             const StirSettings& settings, const vulkan::VulkanContext& context)
    : mSession(backend, run, settings),
      mView(mSession.simulation().smokeGrid()),
      mRenderer(context, run) {}

void GridStirScene::press(double x, double y, VkExtent2D window) {
    if (const auto p = scenePoint(x, y, window)) mSession.press(*p);
}

void GridStirScene::moveTo(double x, double y, VkExtent2D window) {
    if (const auto p = scenePoint(x, y, window)) mSession.moveTo(*p);
}

void GridStirScene::orbit(double dx, double dy) {
    if (mView.grid().dim == 3) mView.orbit(dx, dy);
}

void GridStirScene::zoom(double notches) {
    if (mView.grid().dim == 3) mView.zoom(notches);
}

}  // namespace modeflow::stir
