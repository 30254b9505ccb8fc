#pragma once
/// @file StirView.h
/// How the stir window shows the scene and where the pointer is in it. 2D: the smoke grid's box
/// letterboxed in the window, +y up. 3D: the ray-marched picture (a fixed size, letterboxed) of
/// an orbit camera around the box's centre; the pointer lies on the plane through the centre
/// that faces the camera, so a drag stirs across the screen at the depth of the box's middle.

#include <optional>

#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"
#include "engine/display/Viewport.h"
#include "engine/preview/VolumeView.h"

namespace modeflow::stir {

class StirView {
public:
    /// The 3D picture's size in pixels: ray marching costs per pixel, so it is rendered at a
    /// fixed size and scaled to the window.
    static constexpr int kPictureWidth = 400, kPictureHeight = 300;

    explicit StirView(const MacGrid& smokeGrid) : mGrid(smokeGrid) {}

    /// Where the picture goes in a width × height window.
    display::Viewport viewport(int width, int height) const;
    /// The scene point under the window point (fractions, y down) of a width × height window;
    /// 2D points outside the box are clamped to it; nullopt when the 3D ray misses the plane.
    std::optional<Vec3> scenePoint(double x, double y, int width, int height) const;

    /// The 3D picture's continuous pixel coordinates (x right, y down; pixel (i, j) spans
    /// [i, i+1) × [j, j+1)) of a scene point, and the picture pixels per scene length there;
    /// nullopt behind the camera.
    struct Projection {
        double x = 0.0, y = 0.0;
        double pixelsPerLength = 0.0;
    };
    std::optional<Projection> project(const Vec3& point) const;

    /// Turns the camera by a pointer motion of (dx, dy) window fractions (3D).
    void orbit(double dx, double dy);
    /// Moves the camera closer (positive notches) or away (3D).
    void zoom(double notches);
    const preview::VolumeCamera& camera() const { return mCamera; }
    const MacGrid& grid() const { return mGrid; }

    /// The length that drags and paddles scale with: the box's largest side.
    double boxSize() const;

private:
    MacGrid mGrid;
    preview::VolumeCamera mCamera{-60.0, 25.0, 1.0, 1.0};  ///< whole-cell march steps
};

}  // namespace modeflow::stir
