/// @file SurfaceView.cpp

#include "engine/stir/SurfaceView.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace modeflow::stir {

display::Viewport SurfaceView::viewport(int width, int height) const {
    return display::Viewport::letterbox(width, height, double(kPictureWidth) / kPictureHeight);
}

preview::SurfaceCamera SurfaceView::camera() const {
    const double az = mAzimuthDeg * std::numbers::pi / 180.0,
                 el = mElevationDeg * std::numbers::pi / 180.0;
    preview::SurfaceCamera camera;
    camera.view = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    // Right and up of the picture (SurfaceCamera's frame); the light comes from the viewer's
    // upper left.
    const Vec3 right{-std::sin(az), std::cos(az), 0.0};
    const Vec3 up{-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az), std::cos(el)};
    for (int k = 0; k < 3; ++k) camera.light[k] = camera.view[k] + 0.6 * up[k] - 0.4 * right[k];
    camera.zoom = mZoom;
    return camera;
}

preview::SurfaceProjection SurfaceView::projection() const {
    return preview::SurfaceProjection(mMesh, camera(), kPictureWidth, kPictureHeight);
}

std::optional<MeshHit> SurfaceView::pick(double x, double y, int width, int height) const {
    double u = 0.0, v = 0.0;
    viewport(width, height).toViewport(x, y, width, height, u, v);
    if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return std::nullopt;
    const preview::SurfaceProjection p = projection();
    // From in front of the whole mesh towards it, along the view.
    const Vec3 onPlane = p.pointAt(u * kPictureWidth, v * kPictureHeight);
    Vec3 origin{}, direction{};
    for (int k = 0; k < 3; ++k) {
        origin[k] = onPlane[k] + 2.0 * p.radius() * p.view()[k];
        direction[k] = -p.view()[k];
    }
    return nearestHit(mMesh, origin, direction);
}

void SurfaceView::orbit(double dx, double dy) {
    mAzimuthDeg -= 180.0 * dx;
    // Short of the poles, where z (the picture's up) would be the viewing direction.
    mElevationDeg = std::clamp(mElevationDeg + 90.0 * dy, -80.0, 80.0);
}

void SurfaceView::zoom(double notches) {
    mZoom = std::clamp(mZoom * std::pow(1.1, notches), 0.5, 4.0);
}

}  // namespace modeflow::stir
