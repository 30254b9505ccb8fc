#pragma once
/// @file ImplicitShape.h
/// A solid given by a signed function: positive inside, zero exactly on the surface, and
/// 1-Lipschitz, so |value| is a lower bound of the distance to the surface. Cut-cell measures rely
/// on that bound to skip elements far from the wall.

#include <memory>
#include <string_view>

#include "engine/core/SceneSpec.h"

namespace modeflow {

class ImplicitShape {
public:
    virtual ~ImplicitShape() = default;
    /// Positive inside, 0 on the surface, |value| <= distance to the surface.
    virtual double value(const Vec3& p) const = 0;
};

/// Builds the shape a spec describes, in 2D (z ignored; ball = disk, box = rectangle,
/// ellipsoid = ellipse) or 3D. `voxelSize` sets the resolution of mesh level sets.
/// @throw Error when the kind does not exist in this dimension or the mesh cannot be used.
std::unique_ptr<ImplicitShape> makeShape(const ShapeSpec& spec, int dim, double voxelSize);

}  // namespace modeflow
