#pragma once
/// @file WindTransport.h
/// A wind (`[wind] velocity = U`) through the grid box (engine/README.md, "Wind"): the air moves
/// as u = B + Σ v_k Ψ_k, B a held base flow entering through the box's upstream sides and leaving
/// through the downstream ones, the closed-box modes Ψ_k the disturbance solids and forces make.
/// B = U f(h), f = 1 (a uniform wind) or a boundary layer's power law of the height h over the
/// floor, is divergence-free and steady ((B·∇)B = 0: it varies across itself only), so the
/// momentum equation of the disturbance u' gains the linear terms −(B·∇)u' − (u'·∇)B, whose
/// projection on the modes is
///
///     (D v)_k = −Σ_a U_a ⟨Ψ_k, f ∂_a u' + f' u'_up e_a⟩,   u' = Ψ v.
///
/// ∂_a is the centred difference of the face fluxes along a, within each face lattice (f is
/// constant along a row of it). Beyond the box a lattice reads the inflow's disturbance upstream
/// (0: the wind arrives undisturbed) and its last value downstream (the disturbance leaves
/// unchanged); along a periodic axis it wraps. Then Σ_f F ⋆ f ∂_a F telescopes to the downstream
/// ends alone, and
///
///     vᵀ D v = −½ Σ_a |U_a| ∫_{downstream side of a} f |u'|² dA − Σ_a U_a ∫ f' u'_a u'_up dV,
///
/// the kinetic energy the wind carries out and, in a boundary layer, the shear's production (the
/// energy the disturbance draws from the held flow, or gives it): nothing numerically dissipated.
/// u'_up on a face normal to a is the mean of the four up faces beside it. The faces normal to a
/// at the box's sides along a are the modes' walls, where u'_a vanishes. Between two faces the
/// term weighs by the mean of their ⋆ (one value along a whole box's rows; cut faces differ), so
/// the pairs still cancel.
///
/// Around [[domain]] walls the held flow is the potential flow B = Σ_a U_a B_a the cache holds
/// (precompute/solve/WindBaseFlows.h), and its part G = B − U enters in vorticity form: G is
/// irrotational, so (G·∇)u' + (u'·∇)G = ω' × G + ∇(G·u'), whose gradient the divergence-free
/// modes do not see:
///
///     (D v)_k += −⟨Ψ_k, ω' × G⟩,
///
/// evaluated with the structural coefficients' quadrature (G in the velocity slot). Its share of
/// vᵀDv is the energy the disturbance exchanges with the flow's strain round the walls.

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/basis/VelocityBasis.h"
#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"
#include "engine/dynamics/LinearModalTerm.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/SimulationSettings.h"

namespace modeflow {

class WindTransport final : public LinearModalTerm {
public:
    /// Keeps a reference to `cache`, which must outlive it.
    /// @throw modeflow::Error for a surface basis, a non-finite wind, a boundary layer without a
    ///        floor or over [[domain]] walls, or a face DOF that is not a grid face.
    WindTransport(const BasisCache& cache, const WindSpec& wind);

    int size() const override { return mBasis.modeCount(); }
    void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const override;
    const Eigen::MatrixXd& matrix() const override;

    /// ½ Σ_a |U_a| ∫_{downstream side of a} f |u'|² dA for u' = Ψ v: the power the wind
    /// carries out (computed from the grid, independently of apply).
    double outflowPower(const Eigen::VectorXd& v) const;
    /// Σ_a U_a ∫ f' u'_a u'_up dV: the power the disturbance gives the held shear flow (negative:
    /// draws from it); 0 in a uniform wind. In a whole box vᵀ D v = −outflowPower − shearPower;
    /// around domain walls the potential part's exchange adds to it.
    double shearPower(const Eigen::VectorXd& v) const;

private:
    /// The fluxes Ψ v on every face of the grid (0 on faces that are not DOFs).
    std::vector<double> gridFluxes(const Eigen::VectorXd& v) const;
    /// Samples G = `base` − U at the vorticity elements (mPotentialB, mPotentialC).
    void samplePotentialPart(const std::vector<double>& base);
    /// The mean up-velocity of the four up faces beside the normal-`a` face at `p` (a ≠ up,
    /// p inside the box along a).
    double upVelocityBeside(const std::vector<double>& fluxes, int a,
                            const std::array<int, 3>& p) const;

    const BasisCache& mCache;
    VelocityBasis mBasis;
    MacGrid mGrid;
    WindSpec mWind;
    /// Per face lattice, f and f' at the heights of its rows along the up axis.
    std::array<std::vector<double>, 3> mFactor, mSlope;
    std::vector<double> mStar;  ///< ⋆ of every grid face (0 where no DOF)
    /// Around domain walls: G's components u_b, u_c at the quadrature's elements (else empty).
    Eigen::VectorXd mPotentialB, mPotentialC;
    mutable Eigen::MatrixXd mMatrix;  ///< D, formed by matrix()
};

/// The wind's held flow B on every face of `cache`'s grid (face-normal velocities): Σ_a U_a B_a
/// from the cache's flows around [[domain]] walls when it holds them, else addWind's U f(h).
/// What the grid velocity adds to Ψ v, on both backends.
/// @throw modeflow::Error for a non-finite wind, or a boundary layer over domain walls.
std::vector<double> windBaseFlow(const BasisCache& cache, const WindSpec& wind);

/// What viscosity relaxes the modes toward in `wind` round `cache`'s [[domain]] walls:
/// Σ_a |U_a| c_(a,±), the held flow's Stokes correction (BasisCache::windStokes; at a no-slip
/// wall the held flow's slip diffuses into the modes); empty for a whole box (B = U f(h): its
/// slip along the box's walls is the free stream's). Call after windBaseFlow's checks.
/// @throw modeflow::Error when a correction is not one value per mode.
Eigen::VectorXd windStokesTarget(const BasisCache& cache, const WindSpec& wind);

/// `settings` with their wind's advection of the modes over `cache`'s basis as the fluid's linear
/// term and its Stokes correction as the viscous target (none without a wind). What a CPU
/// simulation or modal stepper of a run is made with; `cache` must outlive what uses the settings.
SimulationSettings withWindTransport(SimulationSettings settings, const BasisCache& cache);

/// `grid` with the sides the wind crosses open to the air (MacGrid::flowThrough): every
/// non-periodic axis along which it blows.
MacGrid withWindThrough(MacGrid grid, const Vec3& wind);

/// The sides where outside air comes into the box `grid`'s smoke, per side 2·axis + (0 low,
/// 1 high): its open sides (MacGrid::open), and the upstream side of every non-periodic axis
/// the wind blows along (none for a wind of 0).
std::array<bool, 6> inflowSides(const MacGrid& grid, const Vec3& wind);

/// The basis grid of a run's air: `spec`'s box, with the sides a wind crosses open
/// (withWindThrough), what the smoke and the particles sample the air velocity on.
MacGrid airGridOf(const GridSpec& spec, const std::optional<WindSpec>& wind);

/// The wind's speed over the floor of `grid` at height h, relative to `velocity`: f(h) = 1 for a
/// uniform wind, min(1, (h / thickness)^exponent) in a boundary layer; and its slope f'(h).
double windFactor(const WindSpec& wind, double height);
double windSlope(const WindSpec& wind, double height);

/// Adds the wind to a face field of `grid` (face-normal velocities): U_a f(h) on every face
/// normal to a, the box's walls along a included (where the wind enters and leaves).
/// @throw modeflow::Error when `faceField` is not one value per face of `grid`.
void addWind(const MacGrid& grid, const WindSpec& wind, std::span<double> faceField);

}  // namespace modeflow
