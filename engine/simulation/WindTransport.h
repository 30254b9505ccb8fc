#pragma once
/// @file WindTransport.h
/// A wind (`[wind] velocity = U`) over a whole grid box (engine/README.md, "Wind"): the air moves
/// as u = U + Σ v_k Ψ_k, U a held base flow entering through the box's upstream sides and leaving
/// through the downstream ones, the closed-box modes Ψ_k the disturbance solids and forces make.
/// U is constant and divergence-free, so the momentum equation of the disturbance u' gains the
/// linear term −(U·∇)u' ((u'·∇)U = 0), whose projection on the modes is
///
///     (D v)_k = −Σ_a U_a ⟨Ψ_k, ∂_a u'⟩,   u' = Ψ v.
///
/// ∂_a is the centred difference of the face fluxes along a, within each face lattice. Beyond the
/// box a lattice reads the inflow's disturbance upstream (0: the wind arrives undisturbed) and its
/// last value downstream (the disturbance leaves unchanged); along a periodic axis it wraps. Then
/// Σ_f F ⋆ ∂_a F telescopes to the downstream ends alone, and
///
///     vᵀ D v = −½ Σ_a |U_a| ∫_{downstream side of a} |u'|² dA,
///
/// exactly the kinetic energy the wind carries out (nothing numerically dissipated; a wind along
/// a periodic axis is a Galilean shift, D antisymmetric). The faces normal to a are the box's
/// walls along a, where the modes' u'_a vanishes: there the sum telescopes to 0.

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/basis/VelocityBasis.h"
#include "engine/core/MacGrid.h"
#include "engine/dynamics/LinearModalTerm.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/SimulationSettings.h"

namespace modeflow {

class WindTransport final : public LinearModalTerm {
public:
    /// Keeps a reference to `cache`, which must outlive it.
    /// @throw modeflow::Error for a surface basis, a non-finite wind, or a face DOF that is not a
    ///        grid face.
    WindTransport(const BasisCache& cache, const Vec3& wind);

    int size() const override { return mBasis.modeCount(); }
    void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const override;
    const Eigen::MatrixXd& matrix() const override;

    /// ½ Σ_a |U_a| ∫_{downstream side of a} |u'|² dA for u' = Ψ v: the power the wind carries
    /// out, −vᵀ D v (computed from the grid, independently of apply).
    double outflowPower(const Eigen::VectorXd& v) const;

private:
    /// The fluxes Ψ v on every face of the grid (0 on faces that are not DOFs).
    std::vector<double> gridFluxes(const Eigen::VectorXd& v) const;

    const BasisCache& mCache;
    VelocityBasis mBasis;
    MacGrid mGrid;
    Vec3 mWind;
    mutable Eigen::MatrixXd mMatrix;  ///< D, formed by matrix()
};

/// `settings` with their wind's advection of the modes over `cache`'s basis as the fluid's linear
/// term (none without a wind). What a CPU simulation or modal stepper of a run is made with;
/// `cache` must outlive what uses the settings.
SimulationSettings withWindTransport(SimulationSettings settings, const BasisCache& cache);

/// `grid` with the sides the wind crosses open to the air (MacGrid::flowThrough): every
/// non-periodic axis along which it blows.
MacGrid withWindThrough(MacGrid grid, const Vec3& wind);

/// The sides across each axis where the wind brings air into the box `grid`: −1 the low side,
/// +1 the high side, 0 none (an axis it does not blow along, a periodic one, or one beyond dim).
std::array<int, 3> inflowSides(const MacGrid& grid, const Vec3& wind);

/// The basis grid of a run's air: `spec`'s box, with the sides a wind crosses open
/// (withWindThrough), what the smoke and the particles sample the air velocity on.
MacGrid airGridOf(const GridSpec& spec, const std::optional<Vec3>& wind);

/// Adds the wind to a face field of `grid` (face-normal velocities): U_a on every face normal to
/// a, the box's walls along a included (where the wind enters and leaves).
/// @throw modeflow::Error when `faceField` is not one value per face of `grid`.
void addWind(const MacGrid& grid, const Vec3& wind, std::span<double> faceField);

}  // namespace modeflow
