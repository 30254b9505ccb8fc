#pragma once
/// @file SurfaceDye.h
/// Dye carried by the flow on a surface, in the surface's scalar basis (seed eq. 6.2): the dye is
/// its mean plus Σ f_i Φ_i, and advection is ḟ = −A(v) f with A(v) = Σ_m v_m A_m antisymmetric,
/// so the midpoint (Cayley) step keeps |f| (the dye's variance) exactly; the mean never moves.
/// [[source]] balls and boxes add their rate at the vertices inside them (SurfaceSources.h).
/// Like any truncated spectral field, the dye rings (Gibbs) near sharp edges, and may dip below 0.

#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "engine/format/BasisCache.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/simulation/SurfaceSources.h"

namespace modeflow {

class SurfaceDye {
public:
    /// @throw modeflow::Error naming the [[source]] (1-based) that covers no vertex of the
    ///        surface, or when the cache is not a surface basis.
    SurfaceDye(const BasisCache& cache, std::span<const SmokeEmitter> emitters);

    /// One step of h from time t, the velocity going from v0 to v1: (I + h/2 K) f' =
    /// (I − h/2 K) f + h s, K = A((v0 + v1)/2), s the emitters active at t.
    void step(const Eigen::VectorXd& v0, const Eigen::VectorXd& v1, double t, double h);

    /// [mean, f_1, …, f_M]: what a checkpoint keeps (surfaceDyeAtVertices gives the vertices').
    const Eigen::VectorXd& state() const { return mState; }
    /// @throw modeflow::Error on a wrong size.
    void setState(const Eigen::VectorXd& state);

private:
    const BasisCache& mCache;
    int mScalars = 0;
    SurfaceSources mSources;
    Eigen::VectorXd mState;
};

}  // namespace modeflow
