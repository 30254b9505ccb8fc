#include "engine/reference/SmokeAdvection.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"
#include "engine/reference/ConservativeTransport.h"
#include "engine/simulation/WindTransport.h"

namespace modeflow::reference {
namespace {

using Field = OutsideAir::Field;

/// A masked trilinear sample: the renormalized value over fluid cells, and the range of the
/// fluid cells of the stencil (for MacCormack's clamp).
struct FluidSample {
    double value = 0.0;
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    bool anyFluid = false;
};

FluidSample sampleFluid(const MacGrid& grid, std::span<const std::uint8_t> mask,
                        std::span<const double> field, const Vec3& gridPoint, double fallback,
                        const OutsideAir* outside, std::optional<OutsideAir::Field> which) {
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
    const double share = outside ? outside->inBoxShare(gridPoint) : 1.0;
    if (share < 1.0) {  // the ghost cells hold what the outside air brings
        const double ghost = outside->value(outside->ghostOf(gridPoint), which);
        sample.value = share * sample.value + (1.0 - share) * ghost;
        sample.lo = std::min(sample.lo, ghost);
        sample.hi = std::max(sample.hi, ghost);
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
      mOutside(mSmoke, mSmoke.open) {  // open sides take in clean air
    requireCellField(mMask.size(), "the fluid mask");
}

void SmokeAdvection::setWind(const WindSpec& wind) {
    mBasis = withWindThrough(mBasis, wind.velocity);
    mOutside = OutsideAir(mSmoke, inflowSides(mSmoke, wind.velocity),
                          {wind.density, wind.temperature, 0.0});  // the wind brings no fuel
}

void SmokeAdvection::setInflows(std::span<const InflowPatch> active) {
    mOutside.setInflows(active);
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
                                                   std::optional<OutsideAir::Field> outside,
                                                   bool ghosts) const {
    std::vector<double> result(field.size(), 0.0);
    const auto cells = std::int64_t(field.size());
    const OutsideAir* air = ghosts ? &mOutside : nullptr;
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < cells; ++c)
        if (mMask[c])
            result[c] = sampleFluid(mSmoke, mMask, field, traces[c], field[c], air, outside).value;
    return result;
}

std::vector<double> SmokeAdvection::advectAlong(std::span<const double> field,
                                                const std::vector<Vec3>& back,
                                                const std::vector<Vec3>& ahead,
                                                AdvectionScheme scheme,
                                                std::optional<OutsideAir::Field> outside) const {
    std::vector<double> forward = semiLagrangian(field, back, outside, true);
    if (scheme == AdvectionScheme::SemiLagrangian) return forward;
    // The traces ahead leave the box where the air leaves it, and the air there has no ghost
    // of outside air: they read the box's own edge (where the air comes in they point inwards).
    const std::vector<double> backward = semiLagrangian(forward, ahead, outside, false);
    std::vector<double> result(field.size(), 0.0);
    const auto cells = std::int64_t(field.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < cells; ++c) {
        if (!mMask[c]) continue;
        const FluidSample bounds =
            sampleFluid(mSmoke, mMask, field, back[c], field[c], &mOutside, outside);
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
        const ConservativeTransport transport(mBasis, mSmoke, mMask, mOutside);
        const std::vector<double> u = transport.faceVelocity(velocity);
        const int substeps = transport.substeps(u, dt);
        transport.advect(u, dt, substeps, fields.density, Field::Density);
        transport.advect(u, dt, substeps, fields.temperature, Field::Temperature);
        if (!fields.fuel.empty()) transport.advect(u, dt, substeps, fields.fuel, Field::Fuel);
        applyEmitters(mSmoke, mMask, emitters, dt, fields.density, fields.temperature, fields.fuel);
        return;
    }
    const std::vector<Vec3> back = backtrace(velocity, dt);
    const std::vector<Vec3> ahead =
        scheme == AdvectionScheme::MacCormack ? backtrace(velocity, -dt) : std::vector<Vec3>{};
    fields.density = advectAlong(fields.density, back, ahead, scheme, Field::Density);
    fields.temperature = advectAlong(fields.temperature, back, ahead, scheme, Field::Temperature);
    if (!fields.fuel.empty())
        fields.fuel = advectAlong(fields.fuel, back, ahead, scheme, Field::Fuel);
    applyEmitters(mSmoke, mMask, emitters, dt, fields.density, fields.temperature, fields.fuel);
}

void SmokeAdvection::step(std::span<const float> velocity, double dt, AdvectionScheme scheme,
                          std::span<const SmokeEmitter> emitters, SmokeFields& fields) const {
    const std::vector<double> wide(velocity.begin(), velocity.end());
    step(wide, dt, scheme, emitters, fields);
}

std::vector<double> SmokeAdvection::advect(std::span<const double> velocity,
                                           std::span<const double> field, double dt,
                                           AdvectionScheme scheme, double* crossed,
                                           std::optional<Field> outside) const {
    requireCellField(field.size(), "the advected field");
    if (scheme == AdvectionScheme::Conservative) {
        const ConservativeTransport transport(mBasis, mSmoke, mMask, mOutside);
        const std::vector<double> u = transport.faceVelocity(velocity);
        std::vector<double> result(field.begin(), field.end());
        const double out = transport.advect(u, dt, transport.substeps(u, dt), result, outside);
        if (crossed) *crossed = out;
        return result;
    }
    const std::vector<Vec3> back = backtrace(velocity, dt);
    const std::vector<Vec3> ahead =
        scheme == AdvectionScheme::MacCormack ? backtrace(velocity, -dt) : std::vector<Vec3>{};
    return advectAlong(field, back, ahead, scheme, outside);
}

double SmokeAdvection::mass(std::span<const double> field) const {
    requireCellField(field.size(), "the field whose mass is asked for");
    double sum = 0.0;
    for (const double value : field) sum += value;
    return sum * mSmoke.cellVolume();
}

}  // namespace modeflow::reference
