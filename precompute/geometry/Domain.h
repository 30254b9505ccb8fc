#pragma once
/// @file Domain.h
/// The fluid domain Ω = {x : χ(x) > 0} (precompute/README.md): the scene's shapes combined in
/// order.

#include <memory>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "precompute/geometry/ImplicitShape.h"

namespace modeflow {

/// χ for a list of `[[domain]]` shapes, applied in order: the first shape starts the domain
/// (whatever its op), then union = max, intersect = min, subtract = min(χ, -χ_shape).
/// Min/max of 1-Lipschitz functions stay 1-Lipschitz, so |χ| never exceeds the distance to ∂Ω.
class Domain {
public:
    /// An empty list means the whole grid box is fluid (χ = +∞).
    /// @throw Error naming the shape (e.g. "[[domain]] #2 (torus): ...") when it cannot be built.
    /// `voxelSize` is the resolution used for mesh level sets (a fraction of the grid spacing).
    Domain(const std::vector<ShapeSpec>& shapes, int dim, double voxelSize);

    double chi(const Vec3& p) const;
    bool isWholeBox() const { return mShapes.empty(); }

private:
    std::vector<std::unique_ptr<ImplicitShape>> mShapes;
    std::vector<CsgOp> mOps;
};

}  // namespace modeflow
