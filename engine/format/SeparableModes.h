#pragma once
/// @file SeparableModes.h
/// Closed-form eigenfields of the discrete operators on a whole grid box (free-slip walls) or
/// torus, or a mix of wall and periodic axes (precompute/README.md, "Closed-form bases"). A mode
/// is a product of one trigonometric factor per axis,
///
///     f_a(x) = cos(θ_a x + φ_a)   or   s_a(x) = sin(θ_a x + φ_a),
///     θ_a = π l_a / n_a on a wall axis, 2π l_a / n_a on a periodic one,  φ_a = shift_a · π/2,
///
/// x in cells along the axis (faces at whole positions, cell centres at half ones):
///
///   velocity  u_a = amplitude_a · s_a(x_a) · Π_{b≠a} f_b(x_b) on the faces of normal a, stored as
///             the flux u_a·|face| (⋆-orthonormal); the discrete divergence is
///             Σ_a amplitude_a σ_a Π_b f_b with σ_a = (2/h_a) sin(θ_a/2), so amplitude ⟂ σ;
///             κ² = Σ_a σ_a².
///   scalar    Φ = amplitude · |cell| · Π_a f_a(x_a) at the cell centres (⋆-orthonormal);
///             μ² = Σ_a σ_a².
///
/// The descriptors are what a cache stores for such a basis (a few dozen bytes a mode instead of
/// a column of the grid), and what a transform evaluates axis by axis.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/core/GridSpec.h"

namespace modeflow {

/// Where a basis came from: the eigensolver (dense columns stored) or closed form (descriptors).
enum class BasisSource : std::int32_t { Eigensolve, ClosedForm };

struct SeparableMode {
    std::array<std::int32_t, 3> wave{0, 0, 0};   ///< l_a (0 on unused axes)
    std::array<std::uint8_t, 3> shift{0, 0, 0};  ///< φ_a in quarter turns: 0 or 1
    /// Velocity: the factor of u_a per axis (normalization included; 0 where u_a vanishes).
    /// Scalar: amplitude[0] (normalization included); the others are 0.
    std::array<double, 3> amplitude{0.0, 0.0, 0.0};
    bool operator==(const SeparableMode&) const = default;
};

/// f_a(x) (or s_a(x) when `sine`) at x = twiceX/2. The angle is reduced exactly (in integers, as a
/// multiple of π/(2n_a)), and multiples of π/2 give exact 0 and ±1.
double separableFactor(const GridSpec& grid, int axis, int wave, int shift, int twiceX, bool sine);

/// σ_a = (2/h_a) sin(θ_a/2), the per-axis eigenvalue's square root.
double axisSigma(const GridSpec& grid, int axis, int wave);

/// The face DOFs of the whole grid box (MacGrid numbering): by normal axis, x fastest, every face
/// but the walls' (on a periodic axis the face at position 0 stands for its plane, and the one at
/// n is not a DOF). What precompute/closedform/WholeBoxDofs gives a closed-form basis.
std::vector<std::int64_t> wholeBoxFaces(const GridSpec& grid);

/// The fluxes of velocity modes through the face DOFs `faces` (CubicalComplex / MacGrid
/// numbering), one column per mode.
Eigen::MatrixXd velocityModeFluxes(const GridSpec& grid, const std::vector<std::int64_t>& faces,
                                   const std::vector<SeparableMode>& modes);
/// The values of scalar modes on the cell DOFs `cells` (x fastest), one column per mode.
Eigen::MatrixXd scalarModeValues(const GridSpec& grid, const std::vector<std::int64_t>& cells,
                                 const std::vector<SeparableMode>& modes);

}  // namespace modeflow
