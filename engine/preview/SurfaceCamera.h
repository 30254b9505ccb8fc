#pragma once
/// @file SurfaceCamera.h
/// How a surface picture looks at its mesh (SurfaceImage.h): an orthographic view along −view,
/// z up on the picture (the camera must not look straight along z), framed on the sphere around
/// the mesh's bounding box centre through its farthest vertex, which fills 90% of the picture's
/// shorter side at zoom 1. SurfaceProjection is that frame for one mesh and picture size: where
/// a point lands, and which ray a pixel is, so a pointer picks what the picture shows.

#include <array>

#include "engine/core/TriangleMesh.h"

namespace modeflow::preview {

struct SurfaceCamera {
    Vec3 view{1.0, -1.4, 0.9};    ///< towards the viewer, any length: the upper right front
    Vec3 light{-0.4, -0.8, 1.0};  ///< towards the light, any length
    double zoom = 1.0;
};

class SurfaceProjection {
public:
    SurfaceProjection(const TriangleMesh& mesh, const SurfaceCamera& camera, int width, int height);

    /// A point's continuous pixel coordinates (x right, y down; pixel (i, j) spans [i, i+1) ×
    /// [j, j+1)) and its depth along the view (larger: nearer the viewer).
    std::array<double, 3> toPicture(const Vec3& point) const;
    /// The point at continuous pixel coordinates (x, y) on the plane through the mesh's centre
    /// that faces the viewer; the pixel's ray runs from there along ±view().
    Vec3 pointAt(double x, double y) const;

    const Vec3& view() const { return mView; }    ///< unit, towards the viewer
    const Vec3& light() const { return mLight; }  ///< unit, towards the light
    /// The framing sphere's radius (scene length).
    double radius() const { return mRadius; }

private:
    Vec3 mView{}, mRight{}, mUp{}, mLight{}, mCentre{};
    double mRadius = 0.0, mScale = 1.0;
    int mWidth = 0, mHeight = 0;
};

}  // namespace modeflow::preview
