/// @file Domain.cpp
#include "precompute/geometry/Domain.h"

#include <algorithm>
#include <limits>
#include <string>

#include "engine/core/Error.h"
#include "precompute/scene/SceneLoader.h"

namespace modeflow {

Domain::Domain(const std::vector<ShapeSpec>& shapes, int dim, double voxelSize) {
    mShapes.reserve(shapes.size());
    mOps.reserve(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        try {
            mShapes.push_back(makeShape(shapes[i], dim, voxelSize));
        } catch (const Error& e) {
            throw Error("[[domain]] #" + std::to_string(i + 1) + " (" +
                        std::string(sceneKeyword(shapes[i].kind)) + "): " + e.what());
        }
        mOps.push_back(shapes[i].op);
    }
}

double Domain::chi(const Vec3& p) const {
    if (mShapes.empty()) return std::numeric_limits<double>::infinity();
    // The first shape starts the domain whatever its op: "subtract" from nothing would leave
    // nothing, which no scene means.
    double chi = mShapes.front()->value(p);
    for (std::size_t i = 1; i < mShapes.size(); ++i) {
        const double v = mShapes[i]->value(p);
        switch (mOps[i]) {
            case CsgOp::Union:
                chi = std::max(chi, v);
                break;
            case CsgOp::Intersect:
                chi = std::min(chi, v);
                break;
            case CsgOp::Subtract:
                chi = std::min(chi, -v);
                break;
        }
    }
    return chi;
}

}  // namespace modeflow
