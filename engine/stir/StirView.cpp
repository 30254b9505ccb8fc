#include "engine/stir/StirView.h"

#include <algorithm>
#include <cmath>

namespace modeflow::stir {

double StirView::boxSize() const {
    double size = 0.0;
    for (int a = 0; a < mGrid.dim; ++a) size = std::max(size, mGrid.spacing[a] * mGrid.cells[a]);
    return size;
}

display::Viewport StirView::viewport(int width, int height) const {
    const double aspect =
        mGrid.dim == 2 ? mGrid.spacing[0] * mGrid.cells[0] / (mGrid.spacing[1] * mGrid.cells[1])
                       : double(kPictureWidth) / kPictureHeight;
    return display::Viewport::letterbox(width, height, aspect);
}

std::optional<Vec3> StirView::scenePoint(double x, double y, int width, int height) const {
    double u = 0.0, v = 0.0;
    viewport(width, height).toViewport(x, y, width, height, u, v);
    if (mGrid.dim == 2) {
        u = std::clamp(u, 0.0, 1.0);
        v = std::clamp(v, 0.0, 1.0);
        return Vec3{mGrid.origin[0] + u * mGrid.spacing[0] * mGrid.cells[0],
                    mGrid.origin[1] + (1.0 - v) * mGrid.spacing[1] * mGrid.cells[1], 0.0};
    }
    // The ray of the picture's pixel under the pointer (the renderer's own camera, so what is
    // under the pointer is where the stirring goes).
    const auto p = preview::volumeViewParams(mGrid, kPictureWidth, kPictureHeight, 1.0f, mCamera);
    const double px = u * kPictureWidth, py = v * kPictureHeight;
    const Vec3 base{p.baseX, p.baseY, p.baseZ}, dx{p.dxX, p.dxY, p.dxZ}, dy{p.dyX, p.dyY, p.dyZ};
    const Vec3 eyeCells{p.eyeX, p.eyeY, p.eyeZ};
    Vec3 eye{}, dir{}, forward{}, centre{};
    for (int a = 0; a < 3; ++a) {
        eye[a] = mGrid.origin[a] + eyeCells[a] * mGrid.spacing[a];
        dir[a] = base[a] + px * dx[a] + py * dy[a];
        forward[a] = base[a] + 0.5 * kPictureWidth * dx[a] + 0.5 * kPictureHeight * dy[a];
        centre[a] = mGrid.origin[a] + 0.5 * mGrid.spacing[a] * mGrid.cells[a];
    }
    double along = 0.0, across = 0.0;
    for (int a = 0; a < 3; ++a) {
        along += (centre[a] - eye[a]) * forward[a];
        across += dir[a] * forward[a];
    }
    if (!(across > 0.0)) return std::nullopt;
    const double t = along / across;
    return Vec3{eye[0] + t * dir[0], eye[1] + t * dir[1], eye[2] + t * dir[2]};
}

std::optional<StirView::Projection> StirView::project(const Vec3& point) const {
    // The inverse of the renderer's rays: the ray through continuous pixel coordinates (X, Y)
    // is forward + (X − W/2) dx + (Y − H/2) dy, with dx ⟂ dy, both ⟂ forward = base + (W/2) dx
    // + (H/2) dy; a point is on it at λ = (point − eye)·forward / |forward|².
    const auto p = preview::volumeViewParams(mGrid, kPictureWidth, kPictureHeight, 1.0f, mCamera);
    const Vec3 dx{p.dxX, p.dxY, p.dxZ}, dy{p.dyX, p.dyY, p.dyZ};
    double toPoint[3], forward[3], along = 0.0, forward2 = 0.0, onX = 0.0, onY = 0.0, dx2 = 0.0,
                                   dy2 = 0.0;
    for (int a = 0; a < 3; ++a) {
        toPoint[a] =
            point[a] - (mGrid.origin[a] + std::array{p.eyeX, p.eyeY, p.eyeZ}[a] * mGrid.spacing[a]);
        forward[a] = std::array{p.baseX, p.baseY, p.baseZ}[a] + 0.5 * kPictureWidth * dx[a] +
                     0.5 * kPictureHeight * dy[a];
    }
    for (int a = 0; a < 3; ++a) {
        along += toPoint[a] * forward[a];
        forward2 += forward[a] * forward[a];
        onX += toPoint[a] * dx[a];
        onY += toPoint[a] * dy[a];
        dx2 += dx[a] * dx[a];
        dy2 += dy[a] * dy[a];
    }
    if (!(along > 0.0)) return std::nullopt;
    // Scale toPoint to the ray of the form forward + s dx + t dy: divide by its forward part.
    const double scale = forward2 / along;
    Projection out;
    out.x = 0.5 * kPictureWidth + scale * onX / dx2;
    out.y = 0.5 * kPictureHeight + scale * onY / dy2;
    out.pixelsPerLength = scale / std::sqrt(dx2);  // a length ℓ across the view moves X by this ℓ
    return out;
}

void StirView::orbit(double dx, double dy) {
    mCamera.azimuthDeg -= 180.0 * dx;
    // Short of the poles, where "up" (z) would be the viewing direction.
    mCamera.elevationDeg = std::clamp(mCamera.elevationDeg + 90.0 * dy, -80.0, 80.0);
}

void StirView::zoom(double notches) {
    mCamera.zoom = std::clamp(mCamera.zoom * std::pow(1.1, notches), 0.5, 2.5);
}

}  // namespace modeflow::stir
