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
    const double aspect = mGrid.dim == 2 ? mGrid.spacing[0] * mGrid.cells[0] /
                                               (mGrid.spacing[1] * mGrid.cells[1])
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

void StirView::orbit(double dx, double dy) {
    mCamera.azimuthDeg -= 180.0 * dx;
    // Short of the poles, where "up" (z) would be the viewing direction.
    mCamera.elevationDeg = std::clamp(mCamera.elevationDeg + 90.0 * dy, -80.0, 80.0);
}

void StirView::zoom(double notches) {
    mCamera.zoom = std::clamp(mCamera.zoom * std::pow(1.1, notches), 0.5, 2.5);
}

}  // namespace modeflow::stir
