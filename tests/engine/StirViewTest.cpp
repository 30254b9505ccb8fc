/// Where the stir window's pointer is in the scene.

#include <gtest/gtest.h>

#include <cmath>

#include "engine/stir/StirView.h"

namespace modeflow::stir {
namespace {

MacGrid grid(int dim) {
    MacGrid g;
    g.dim = dim;
    g.cells = {40, 20, dim == 3 ? 30 : 1};
    g.origin = {-2.0, -1.0, -1.5};
    g.spacing = {0.1, 0.1, 0.1};
    return g;
}

TEST(StirViewTest, TwoDimensionalBoxIsLetterboxedWithYUp) {
    const StirView view(grid(2));
    const display::Viewport v = view.viewport(800, 600);
    EXPECT_EQ(v.width, 800);
    EXPECT_EQ(v.height, 400) << "the 4 × 2 box keeps its shape";
    EXPECT_EQ(v.y, 100);
    const auto centre = view.scenePoint(0.5, 0.5, 800, 600);
    ASSERT_TRUE(centre);
    EXPECT_NEAR((*centre)[0], 0.0, 1e-12);
    EXPECT_NEAR((*centre)[1], 0.0, 1e-12);
    const auto topLeft = view.scenePoint(0.0, 100.0 / 600.0, 800, 600);
    EXPECT_NEAR((*topLeft)[0], -2.0, 1e-12);
    EXPECT_NEAR((*topLeft)[1], 1.0, 1e-12) << "the window's top is the box's top";
    const auto margin = view.scenePoint(0.5, 0.01, 800, 600);
    EXPECT_NEAR((*margin)[1], 1.0, 1e-12) << "points in the margin are clamped to the box";
}

TEST(StirViewTest, ThreeDimensionalPointerLiesOnThePlaneFacingTheCamera) {
    StirView view(grid(3));
    const int w = 1000, h = 600;
    const auto centre = view.scenePoint(0.5, 0.5, w, h);
    ASSERT_TRUE(centre);
    EXPECT_NEAR((*centre)[0], 0.0, 1e-6);
    EXPECT_NEAR((*centre)[1], 0.0, 1e-6);
    EXPECT_NEAR((*centre)[2], 0.0, 1e-6);
    // Up on the screen is up in the scene (the camera's up has a positive z), and a point
    // right of the centre stays at the centre's depth along the view.
    const auto above = view.scenePoint(0.5, 0.3, w, h);
    EXPECT_GT((*above)[2], 0.1);
    const auto before = *view.scenePoint(0.7, 0.5, w, h);
    view.orbit(0.25, 0.0);
    const auto after = *view.scenePoint(0.7, 0.5, w, h);
    EXPECT_GT(std::abs(after[0] - before[0]) + std::abs(after[1] - before[1]), 0.1)
        << "orbiting turns the plane the pointer lies on";
    view.orbit(0.0, 5.0);
    EXPECT_LE(view.camera().elevationDeg, 80.0) << "short of the pole";
    view.zoom(100.0);
    EXPECT_LE(view.camera().zoom, 2.5);
}

TEST(StirViewTest, ProjectionInvertsThePointerRay) {
    StirView view(grid(3));
    view.orbit(0.1, 0.05);
    view.zoom(1.0);
    // A window of the picture's aspect: the viewport is the whole window.
    const int w = 2 * StirView::kPictureWidth, h = 2 * StirView::kPictureHeight;
    for (const auto& [x, y] : {std::pair{0.5, 0.5}, std::pair{0.2, 0.7}, std::pair{0.9, 0.1}}) {
        const auto point = view.scenePoint(x, y, w, h);
        ASSERT_TRUE(point);
        const auto pixel = view.project(*point);
        ASSERT_TRUE(pixel);
        // To the camera parameters' float32 precision.
        EXPECT_NEAR(pixel->x, x * StirView::kPictureWidth, 1e-4);
        EXPECT_NEAR(pixel->y, y * StirView::kPictureHeight, 1e-4);
    }
    // Across the view, a length covers pixelsPerLength pixels per unit.
    const auto a = view.scenePoint(0.5, 0.5, w, h), b = view.scenePoint(0.6, 0.5, w, h);
    const double length = std::hypot((*b)[0] - (*a)[0], (*b)[1] - (*a)[1], (*b)[2] - (*a)[2]);
    EXPECT_NEAR(length * view.project(*a)->pixelsPerLength, 0.1 * StirView::kPictureWidth, 1e-4);
}

}  // namespace
}  // namespace modeflow::stir
