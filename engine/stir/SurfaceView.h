#pragma once
/// @file SurfaceView.h
/// How the stir window shows a surface scene and what the pointer touches: the mesh drawn by an
/// orbit camera (preview::SurfaceCamera: orthographic, z up, lit from over the viewer's left
/// shoulder so the side in view is always lit) into a picture of a fixed size, letterboxed in
/// the window; the pointer's ray picks the nearest point of the mesh under it.

#include <optional>

#include "engine/core/TriangleMesh.h"
#include "engine/display/Viewport.h"
#include "engine/preview/SurfaceCamera.h"
#include "engine/stir/MeshRayHit.h"

namespace modeflow::stir {

class SurfaceView {
public:
    /// The picture's size in pixels (drawn on the CPU, scaled to the window).
    static constexpr int kPictureWidth = 640, kPictureHeight = 480;

    /// Keeps a reference to `mesh`, which must outlive the view.
    explicit SurfaceView(const TriangleMesh& mesh) : mMesh(mesh) {}

    /// Where the picture goes in a width × height window.
    display::Viewport viewport(int width, int height) const;
    /// The mesh's point under the window point (fractions, y down) of a width × height window;
    /// nullopt where the pointer is off the mesh.
    std::optional<MeshHit> pick(double x, double y, int width, int height) const;

    /// Turns the camera by a pointer motion of (dx, dy) window fractions.
    void orbit(double dx, double dy);
    /// Moves the camera closer (positive notches) or away.
    void zoom(double notches);
    preview::SurfaceCamera camera() const;
    /// The projection of the picture (kPictureWidth × kPictureHeight).
    preview::SurfaceProjection projection() const;

private:
    const TriangleMesh& mMesh;
    double mAzimuthDeg = -55.0, mElevationDeg = 25.0, mZoom = 1.0;
};

}  // namespace modeflow::stir
