#pragma once
/// @file OutsideAir.h
/// What the air beyond the box's inflow sides carries (engine/README.md, "Inflows"): one ghost
/// cell half a smoke cell beyond each smoke cell along each side, holding a density, a
/// temperature and a fuel — the base values (the wind's; clean air, 0, on open sides) or, where an
/// active `[[inflow]]` meets the side, its own. Both backends' smoke advections read the ghosts
/// by the rules here (inBoxShare, ghostOf; shaders/SmokeAdvect.glsl repeats them in float32), the
/// conservative one by each side face's own ghost (ghostIndex).
///
/// Ghosts of side 2·a + h follow one another along the other two axes b < c (i_b + n_b · i_c),
/// the sides in order x_min, x_max, y_min, ... (a 2D grid's z axis has one cell).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/simulation/InflowPatch.h"

namespace modeflow {

class OutsideAir {
public:
    enum class Field { Density = 0, Temperature = 1, Fuel = 2 };

    /// `sides`: per side, 2·axis + (0 low, 1 high), whether air comes in across it; `base`: what
    /// it carries there (density, temperature, fuel).
    OutsideAir(const MacGrid& smokeGrid, std::array<bool, 6> sides,
               std::array<double, 3> base = {0.0, 0.0, 0.0});

    const std::array<bool, 6>& sides() const { return mSides; }
    /// The ghosts over the base: each active patch's values where its shape holds the ghost's
    /// point on the side's plane (the first patch listed wins).
    void setInflows(std::span<const InflowPatch> active);

    std::int64_t ghostCount() const { return std::int64_t(mValues.size()); }
    /// The ghost beyond the smoke cell `cell` of `side` (its coordinate across the side unused).
    std::int64_t ghostIndex(int side, const std::array<int, 3>& cell) const;
    /// The share of a trilinear sample at `gridPoint` (smoke-cell units) its in-box stencil
    /// gives: below 1 within half a cell of an inflow side, where the ghosts take the rest.
    double inBoxShare(const Vec3& gridPoint) const;
    /// The ghost such a sample reads: beyond the inflow side it reaches farthest past (the first
    /// such side on a tie), at the cell its other coordinates fall in (clamped to the box, wrapped
    /// along periodic axes).
    std::int64_t ghostOf(const Vec3& gridPoint) const;
    /// `field` of a ghost; none: clean air (0).
    double value(std::int64_t ghost, std::optional<Field> field) const;
    /// The ghosts as float32 texels (density, temperature, fuel, 0) for the device; one of zeros
    /// when there are none.
    std::vector<float> texels() const;

    /// The smoke cells of `patch`'s side that it covers and that lie in the fluid (`fluidMask`,
    /// one entry per smoke cell).
    std::int64_t coveredFluidCells(const InflowPatch& patch,
                                   std::span<const std::uint8_t> fluidMask) const;

private:
    /// The world point on `side`'s plane beside the cell.
    Vec3 sidePoint(int side, const std::array<int, 3>& cell) const;

    MacGrid mGrid;
    std::array<bool, 6> mSides;
    std::array<double, 3> mBase;
    std::array<std::int64_t, 7> mOffset{};  ///< first ghost of each side, then the count
    std::vector<std::array<double, 3>> mValues;
};

/// @throw modeflow::Error naming the inflow (1-based) when one covers no fluid cell of its side,
/// or lies on a side no air comes in across.
void requireInflowsMeetFluid(const OutsideAir& outside, std::span<const InflowPatch> patches,
                             std::span<const std::uint8_t> fluidMask);

}  // namespace modeflow
