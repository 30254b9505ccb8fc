#include "engine/reference/SmokeAdvection.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"
#include "engine/reference/ConservativeTransport.h"
#include "engine/simulation/WindTransport.h"

namespace modeflow::reference {
namespace {

/// A masked trilinear sample: the renormalized value over fluid cells, and the range of the
/// fluid cells of the stencil (for MacCormack's clamp).
struct FluidSample {
    double value = 0.0;
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    bool anyFluid = false;
};

/// The share of a sample at `gridPoint` that its in-box stencil gives: below 1 within a cell of
/// an inflow side, where ghost cells beyond the side (centres half a cell out) hold the inflow's
/// clean air and the trilinear weights reach them.
double inBoxShare(const MacGrid& grid, const std::array<bool, 6>& inflow, const Vec3& gridPoint) {
    double share = 1.0;
    for (int a = 0; a < grid.dim; ++a) {
        if (inflow[std::size_t(2 * a)]) share *= std::clamp(gridPoint[a] + 0.5, 0.0, 1.0);
        if (inflow[std::size_t(2 * a + 1)])
            share *= std::clamp(grid.cells[a] + 0.5 - gridPoint[a], 0.0, 1.0);
    }
    return share;
}

FluidSample sampleFluid(const MacGrid& grid, std::span<const std::uint8_t> mask,
                        std::span<const double> field, const Vec3& gridPoint, double fallback,
                        const std::array<bool, 6>& inflow, double inflowValue) {
    const CellStencil stencil = cellStencil(grid, gridPoint);
    FluidSample sample;
    double sum = 0.0, weight = 0.0;
    for (int c = 0; c < stencil.count; ++c) {
        const std::int64_t cell = stencil.cell[c];
        if (!mask[cell]) continue;
        sum += stencil.weight[c] * field[cell];
        weight += stencil.weight[c];
        sample.lo = std::min(sample.lo, field[cell]);
        sample.hi = std::max(sample.hi, field[cell]);
        sample.anyFluid = true;
    }
    sample.value = weight > 0.0 ? sum / weight : fallback;
    const double share = inBoxShare(grid, inflow, gridPoint);
    if (share < 1.0) {  // the ghost cells hold the inflow's value
        sample.value = share * sample.value + (1.0 - share) * inflowValue;
        sample.lo = std::min(sample.lo, inflowValue);
        sample.hi = std::max(sample.hi, inflowValue);
    }
    return sample;
}

}  // namespace

SmokeAdvection::SmokeAdvection(const MacGrid& basisGrid, int scale,
                               std::vector<std::uint8_t> fluidMask)
    : mBasis(basisGrid),
      mScale(scale),
      mSmoke(basisGrid.refined(scale)),
      mMask(std::move(fluidMask)),
      mInflow(mSmoke.open) {  // open sides take in clean air
    requireCellField(mMask.size(), "the fluid mask");
}

void SmokeAdvection::setWind(const WindSpec& wind) {
    mBasis = withWindThrough(mBasis, wind.velocity);
    mInflow = inflowSides(mSmoke, wind.velocity);
    mInflowDensity = wind.density;
    mInflowTemperature = wind.temperature;
}

void SmokeAdvection::requireCellField(std::size_t size, const char* what) const {
    if (size != std::size_t(mSmoke.cellCount()))
        throw Error(std::string("smoke advection: ") + what + " has " + std::to_string(size) +
                    " values, the smoke grid " + std::to_string(mSmoke.cellCount()) + " cells");
}

std::vector<Vec3> SmokeAdvection::backtrace(std::span<const double> velocity, double dt) const {
    requireFaceField(mBasis, velocity.size(), "smoke advection velocity");
    // Velocity (world units per time) times this gives smoke cells per step.
    Vec3 step{0.0, 0.0, 0.0};
    for (int a = 0; a < mSmoke.dim; ++a) step[a] = dt / mSmoke.spacing[a];
    const auto velocityAt = [&](const Vec3& g) {
        Vec3 basisPoint = g;
        for (int a = 0; a < mSmoke.dim; ++a) basisPoint[a] = g[a] / mScale;
        return sampleVelocityGrid(mBasis, velocity, basisPoint);
    };
    std::vector<Vec3> traces(mMask.size());
    // Every loop over the cells below writes its own cell only: split over OpenMP's threads
    // (one result whatever their count).
#pragma omp parallel for schedule(static)
    for (int z = 0; z < mSmoke.cells[2]; ++z)
        for (int y = 0; y < mSmoke.cells[1]; ++y)
            for (int x = 0; x < mSmoke.cells[0]; ++x) {
                const std::int64_t c = mSmoke.cellIndex(x, y, z);
                if (!mMask[c]) continue;
                const Vec3 start{x + 0.5, y + 0.5, z + 0.5};
                const Vec3 u0 = velocityAt(start);
                Vec3 mid;
                for (int a = 0; a < 3; ++a) mid[a] = start[a] - 0.5 * (u0[a] * step[a]);
                const Vec3 u1 = velocityAt(mid);
                for (int a = 0; a < 3; ++a) traces[c][a] = start[a] - u1[a] * step[a];
            }
    return traces;
}

std::vector<double> SmokeAdvection::semiLagrangian(std::span<const double> field,
                                                   const std::vector<Vec3>& traces,
                                                   double inflowValue, bool ghosts) const {
    std::vector<double> result(field.size(), 0.0);
    const auto cells = std::int64_t(field.size());
    const std::array<bool, 6> inflow = ghosts ? mInflow : std::array<bool, 6>{};
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < cells; ++c)
        if (mMask[c])
            result[c] =
                sampleFluid(mSmoke, mMask, field, traces[c], field[c], inflow, inflowValue).value;
    return result;
}

std::vector<double> SmokeAdvection::advectAlong(std::span<const double> field,
                                                const std::vector<Vec3>& back,
                                                const std::vector<Vec3>& ahead,
                                                AdvectionScheme scheme, double inflowValue) const {
    std::vector<double> forward = semiLagrangian(field, back, inflowValue, true);
    if (scheme == AdvectionScheme::SemiLagrangian) return forward;
    // The traces ahead leave the box where the air leaves it, and the air there has no ghost
    // of outside air: they read the box's own edge (where the air comes in they point inwards).
    const std::vector<double> backward = semiLagrangian(forward, ahead, inflowValue, false);
    std::vector<double> result(field.size(), 0.0);
    const auto cells = std::int64_t(field.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < cells; ++c) {
        if (!mMask[c]) continue;
        const FluidSample bounds =
            sampleFluid(mSmoke, mMask, field, back[c], field[c], mInflow, inflowValue);
        const double corrected = forward[c] + 0.5 * (field[c] - backward[c]);
        result[c] = bounds.anyFluid ? std::clamp(corrected, bounds.lo, bounds.hi) : forward[c];
    }
    return result;
}

void SmokeAdvection::step(std::span<const double> velocity, double dt, AdvectionScheme scheme,
                          std::span<const SmokeEmitter> emitters, SmokeFields& fields) const {
    requireCellField(fields.density.size(), "the density");
    requireCellField(fields.temperature.size(), "the temperature");
    if (!fields.fuel.empty()) requireCellField(fields.fuel.size(), "the fuel");
    if (scheme == AdvectionScheme::Conservative) {
        const ConservativeTransport transport(mBasis, mSmoke, mMask, mInflow);
        const std::vector<double> u = transport.faceVelocity(velocity);
        const int substeps = transport.substeps(u, dt);
        transport.advect(u, dt, substeps, fields.density, mInflowDensity);
        transport.advect(u, dt, substeps, fields.temperature, mInflowTemperature);
        if (!fields.fuel.empty()) transport.advect(u, dt, substeps, fields.fuel, 0.0);
        applyEmitters(mSmoke, mMask, emitters, dt, fields.density, fields.temperature, fields.fuel);
        return;
    }
    const std::vector<Vec3> back = backtrace(velocity, dt);
    const std::vector<Vec3> ahead =
        scheme == AdvectionScheme::MacCormack ? backtrace(velocity, -dt) : std::vector<Vec3>{};
    fields.density = advectAlong(fields.density, back, ahead, scheme, mInflowDensity);
    fields.temperature = advectAlong(fields.temperature, back, ahead, scheme, mInflowTemperature);
    if (!fields.fuel.empty())  // the wind brings in no fuel
        fields.fuel = advectAlong(fields.fuel, back, ahead, scheme, 0.0);
    applyEmitters(mSmoke, mMask, emitters, dt, fields.density, fields.temperature, fields.fuel);
}

void SmokeAdvection::step(std::span<const float> velocity, double dt, AdvectionScheme scheme,
                          std::span<const SmokeEmitter> emitters, SmokeFields& fields) const {
    const std::vector<double> wide(velocity.begin(), velocity.end());
    step(wide, dt, scheme, emitters, fields);
}

std::vector<double> SmokeAdvection::advect(std::span<const double> velocity,
                                           std::span<const double> field, double dt,
                                           AdvectionScheme scheme, double* crossed) const {
    requireCellField(field.size(), "the advected field");
    if (scheme == AdvectionScheme::Conservative) {
        const ConservativeTransport transport(mBasis, mSmoke, mMask, mInflow);
        const std::vector<double> u = transport.faceVelocity(velocity);
        std::vector<double> result(field.begin(), field.end());
        const double out = transport.advect(u, dt, transport.substeps(u, dt), result, 0.0);
        if (crossed) *crossed = out;
        return result;
    }
    const std::vector<Vec3> back = backtrace(velocity, dt);
    const std::vector<Vec3> ahead =
        scheme == AdvectionScheme::MacCormack ? backtrace(velocity, -dt) : std::vector<Vec3>{};
    return advectAlong(field, back, ahead, scheme, 0.0);
}

double SmokeAdvection::mass(std::span<const double> field) const {
    requireCellField(field.size(), "the field whose mass is asked for");
    double sum = 0.0;
    for (const double value : field) sum += value;
    return sum * mSmoke.cellVolume();
}

}  // namespace modeflow::reference
