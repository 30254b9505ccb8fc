#pragma once
/// @file ConservativeTransport.h
/// The flux form of smoke advection (`[smoke] advection = "conservative"`; engine/README.md,
/// "Conservative smoke"), CPU reference: what a cell loses through a face its neighbour gains, so
/// the smoke's mass changes only by what crosses the box's sides (and what emitters and fire add).
///
/// On the smoke grid each face carries the normal velocity the basis grid's face field gives at
/// its centre (MacSampling.h; the basis faces themselves at resolution_scale 1). A face moves
/// smoke when both its cells are fluid, or when it lies on a side the air crosses (open, or a
/// wind's) beside a fluid cell; walls and faces beside cells outside Ω move none. Its flux is
/// u·φ_face·area, φ_face the upwind cell's value plus half its minmod-limited slope along the
/// face's normal (MUSCL; first order where a neighbour the slope needs is missing), or beyond an
/// inflow side the value its ghost holds (OutsideAir::ghostIndex). Forward Euler substeps keep
/// Σ_a |u_a| h / h_a ≤ ½ in every cell (a TVD step: no new extrema but those the velocity's own
/// divergence makes, which a reduced basis keeps to round-off).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/simulation/OutsideAir.h"

namespace modeflow::reference {

class ConservativeTransport {
public:
    /// `air`: the basis grid the velocity lives on (its open sides and a wind's);
    /// `smokeGrid`: air.refined(scale); `fluidMask`: one entry per smoke cell, non-zero inside Ω;
    /// `outside`: what the ghost cells beyond the inflow sides hold (kept by reference).
    ConservativeTransport(const MacGrid& air, const MacGrid& smokeGrid,
                          std::span<const std::uint8_t> fluidMask, const OutsideAir& outside);

    /// The smoke grid's face velocities for a face field `velocity` of the air grid, in
    /// MacGrid::faceIndex order of the smoke grid (0 on faces that move no smoke, and where the
    /// velocity is not finite).
    std::vector<double> faceVelocity(std::span<const double> velocity) const;
    /// Forward Euler substeps that keep the step within the TVD limit for `faceVelocity`
    /// (simulation/FluxSubsteps.h).
    /// @throw modeflow::Error when that takes more than maxFluxSubsteps.
    int substeps(std::span<const double> faceVelocity, double dt) const;

    /// Advects `field` over dt in `substeps` steps; ghost cells beyond inflow sides hold the
    /// outside air's `which` (none: clean air). Returns the mass that crossed the box's sides
    /// outwards (negative: inwards).
    double advect(std::span<const double> faceVelocity, double dt, int substeps,
                  std::vector<double>& field, std::optional<OutsideAir::Field> which) const;

private:
    /// Whether the normal-`axis` smoke face at `p` moves smoke.
    bool moves(int axis, const std::array<int, 3>& p) const;

    MacGrid mAir, mSmoke;
    std::span<const std::uint8_t> mMask;
    const OutsideAir& mOutside;
    std::uint32_t mCrossable;  ///< mAir.crossableSideBits()
};

}  // namespace modeflow::reference
