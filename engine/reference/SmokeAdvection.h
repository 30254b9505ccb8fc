#pragma once
/// @file SmokeAdvection.h
/// Smoke (density and temperature) advection on the smoke grid, the double-precision CPU
/// reference of the device kernels (engine/README.md; engine/device/SmokeAdvection).
///
/// The smoke grid is `basisGrid.refined(scale)`; smoke values are concentrations per smoke cell
/// (cellIndex order). The velocity is a face field of the basis grid, sampled with the MAC rule
/// (MacSampling.h). A per-smoke-cell fluid mask (1 inside Ω, 0 outside) confines the smoke:
///
/// - Semi-Lagrangian: from each fluid cell centre an RK2 (midpoint) backtrace, then a
///   cell-centred trilinear sample of the old field in which only fluid cells take part, their
///   weights renormalized to sum 1. Counting outside cells as zeros would drain smoke into the
///   walls; renormalizing extrapolates the fluid values across the wall (a zero-flux, Neumann
///   wall for the scalar) and keeps every value a convex combination of fluid values, so no new
///   extrema. A trace whose stencil holds no fluid cell with positive weight (it left Ω) keeps the
///   cell's own old value.
/// - MacCormack (Selle et al. 2008): forward φ̂ = SL(φ, dt), backward φ̃ = SL(φ̂, −dt), then
///   φ̂ + (φ − φ̃)/2, clamped to the min and max of φ over the fluid cells of the forward trace's
///   stencil: second order where the field is smooth, and no new extrema where it is not.
///
/// Open sides, and with a wind (setWind) the box's upstream sides, let outside air in: ghost
/// cells half a cell beyond them hold what it brings (OutsideAir.h: clean air, or the wind's
/// density and temperature, or an `[[inflow]]`'s values where it meets the side; setInflows)
/// and take their trilinear share of a trace that ends within a cell of the side (and of
/// MacCormack's clamp range). Downstream, traces come from inside the box and the
/// smoke leaves; the clamp to the box there is a zero-gradient outflow.
///
/// Cells outside Ω always come out exactly 0 (nothing leaks out of Ω). Emitters are applied
/// after the advection. Backtraces run in smoke-grid units, as on the device, so both pick the
/// same stencils where the velocity vanishes.
///
/// Neither scheme conserves mass: interpolation is not a flux form, the interpolated MAC
/// velocity is divergence-free only cell by cell, and MacCormack's clamp lifts undershoots, so
/// it gains mass on features only a few cells wide (tests/engine/SmokeAdvectionTest.cpp
/// measures both). The third, `conservative`, is a flux form (ConservativeTransport.h).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"
#include "engine/simulation/OutsideAir.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/simulation/SmokeFields.h"

namespace modeflow::reference {

class SmokeAdvection {
public:
    /// `fluidMask`: one entry per cell of basisGrid.refined(scale), non-zero inside Ω.
    /// @throw modeflow::Error when scale < 1 or the mask has the wrong size.
    SmokeAdvection(const MacGrid& basisGrid, int scale, std::vector<std::uint8_t> fluidMask);

    const MacGrid& basisGrid() const { return mBasis; }
    const MacGrid& smokeGrid() const { return mSmoke; }
    int scale() const { return mScale; }
    const std::vector<std::uint8_t>& fluidMask() const { return mMask; }

    /// One step of both fields: advection by `velocity` (a face field of the basis grid) over
    /// `dt` with `scheme`, then the emitters.
    /// @throw modeflow::Error when a field or the velocity has the wrong size.
    void step(std::span<const double> velocity, double dt, AdvectionScheme scheme,
              std::span<const SmokeEmitter> emitters, SmokeFields& fields) const;
    /// The same with a float32 face field (converted to double first).
    void step(std::span<const float> velocity, double dt, AdvectionScheme scheme,
              std::span<const SmokeEmitter> emitters, SmokeFields& fields) const;

    /// One field advected (no emitters), the ghosts holding the outside air's `outside` (none:
    /// clean air). `crossed`, with the conservative scheme: where the mass that crossed the box's
    /// sides outwards is put.
    std::vector<double> advect(std::span<const double> velocity, std::span<const double> field,
                               double dt, AdvectionScheme scheme, double* crossed = nullptr,
                               std::optional<OutsideAir::Field> outside = std::nullopt) const;

    /// The wind blowing through the box ([wind]): the sides it crosses carry the velocity they
    /// hold (MacGrid::flowThrough), and its upstream sides become inflows of its air. Before
    /// setInflows.
    void setWind(const WindSpec& wind);
    /// The `[[inflow]]` patches letting air in from now on (OutsideAir::setInflows).
    void setInflows(std::span<const InflowPatch> active);
    const OutsideAir& outsideAir() const { return mOutside; }

    /// Σ concentration × smoke cell volume.
    double mass(std::span<const double> field) const;

private:
    /// Where the RK2 trace from each fluid cell centre ends after −dt·u (smoke-grid units).
    std::vector<Vec3> backtrace(std::span<const double> velocity, double dt) const;
    /// `outside`: the field of the outside air the ghost cells beyond the inflow sides hold
    /// (none: clean air), when `ghosts`; without, the stencils clamp to the box on every side.
    std::vector<double> semiLagrangian(std::span<const double> field,
                                       const std::vector<Vec3>& traces,
                                       std::optional<OutsideAir::Field> outside, bool ghosts) const;
    /// `ahead`: the traces over −dt (MacCormack's backward step), unused by semi-Lagrangian.
    std::vector<double> advectAlong(std::span<const double> field, const std::vector<Vec3>& back,
                                    const std::vector<Vec3>& ahead, AdvectionScheme scheme,
                                    std::optional<OutsideAir::Field> outside) const;
    void requireCellField(std::size_t size, const char* what) const;

    MacGrid mBasis;
    int mScale;
    MacGrid mSmoke;
    std::vector<std::uint8_t> mMask;
    /// What the air coming in across the inflow sides (inflowSides) carries.
    OutsideAir mOutside;
};

}  // namespace modeflow::reference
