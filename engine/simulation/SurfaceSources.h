#pragma once
/// @file SurfaceSources.h
/// The dye's [[source]] balls and boxes on a surface, projected once on its scalar basis: each
/// adds its density rate at the vertices inside it, which is the mean rate (its ⋆0-weighted
/// share of the surface) and Φᵀ⋆0 s on the modes. Both backends' dye steps take their rate here.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "engine/simulation/SmokeEmitter.h"

namespace modeflow {

class SurfaceSources {
public:
    /// @throw modeflow::Error naming the [[source]] (1-based) that covers no vertex of the
    ///        surface, or when the cache is not a surface basis.
    SurfaceSources(const BasisCache& cache, std::span<const SmokeEmitter> emitters);

    /// The rate of the sources active at time t, as the dye's state: [mean rate, Φᵀ⋆0 s].
    Eigen::VectorXd rateAt(double t) const;

private:
    struct Source {
        SmokeEmitter emitter;
        Eigen::VectorXd projection;  ///< per unit of density rate
    };
    int mScalars = 0;
    std::vector<Source> mSources;
};

}  // namespace modeflow
