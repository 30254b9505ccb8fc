/// @file SurfaceCamera.cpp

#include "engine/preview/SurfaceCamera.h"

#include <algorithm>
#include <cmath>

#include "engine/core/Vec3Math.h"

namespace modeflow::preview {

SurfaceProjection::SurfaceProjection(const TriangleMesh& mesh, const SurfaceCamera& camera,
                                     int width, int height)
    : mView(normalized(camera.view)),
      mRight(normalized(cross({0.0, 0.0, 1.0}, mView))),
      mUp(cross(mView, mRight)),
      mLight(normalized(camera.light)),
      mWidth(width),
      mHeight(height) {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const Vec3& p : mesh.vertices)
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    mCentre = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    for (const Vec3& p : mesh.vertices)
        mRadius = std::max(mRadius, std::sqrt(dot(sub(p, mCentre), sub(p, mCentre))));
    mScale = camera.zoom * 0.45 * std::min(width, height) / mRadius;
}

std::array<double, 3> SurfaceProjection::toPicture(const Vec3& point) const {
    const Vec3 d = sub(point, mCentre);
    return {0.5 * mWidth + mScale * dot(d, mRight), 0.5 * mHeight - mScale * dot(d, mUp),
            dot(d, mView)};
}

Vec3 SurfaceProjection::pointAt(double x, double y) const {
    const double across = (x - 0.5 * mWidth) / mScale, up = (0.5 * mHeight - y) / mScale;
    Vec3 p{};
    for (int a = 0; a < 3; ++a) p[a] = mCentre[a] + across * mRight[a] + up * mUp[a];
    return p;
}

}  // namespace modeflow::preview
