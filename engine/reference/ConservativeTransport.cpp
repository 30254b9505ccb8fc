#include "engine/reference/ConservativeTransport.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacSampling.h"
#include "engine/simulation/FluxSubsteps.h"

namespace modeflow::reference {
namespace {

double minmod(double a, double b) {
    if (a * b <= 0.0) return 0.0;
    return std::abs(a) < std::abs(b) ? a : b;
}

}  // namespace

ConservativeTransport::ConservativeTransport(const MacGrid& air, const MacGrid& smokeGrid,
                                             std::span<const std::uint8_t> fluidMask,
                                             const OutsideAir& outside)
    : mAir(air),
      mSmoke(smokeGrid),
      mMask(fluidMask),
      mOutside(outside),
      mCrossable(air.crossableSideBits()) {}

bool ConservativeTransport::moves(int axis, const std::array<int, 3>& p) const {
    std::array<int, 3> lower = p;
    lower[axis] = mSmoke.wrap(axis, p[axis] - 1);
    const int n = mSmoke.cells[axis];
    const bool hasLower = mSmoke.periodic[axis] || p[axis] > 0;
    const bool hasUpper = mSmoke.periodic[axis] || p[axis] < n;
    const auto fluid = [&](const std::array<int, 3>& c) {
        return mMask[std::size_t(mSmoke.cellIndex(c[0], c[1], c[2]))] != 0;
    };
    if (hasLower && hasUpper) return fluid(lower) && fluid(p);
    const int side = 2 * axis + (hasLower ? 1 : 0);
    return ((mCrossable >> side) & 1u) != 0 && fluid(hasLower ? lower : p);
}

std::vector<double> ConservativeTransport::faceVelocity(std::span<const double> velocity) const {
    requireFaceField(mAir, velocity.size(), "conservative smoke advection velocity");
    std::vector<double> u(std::size_t(mSmoke.faceTotal()), 0.0);
    const double scale = double(mSmoke.cells[0]) / mAir.cells[0];
    for (int axis = 0; axis < mSmoke.dim; ++axis)
        forEachFace(mSmoke, axis, [&](std::int64_t face, const std::array<int, 3>& p) {
            if (!moves(axis, p)) return;
            Vec3 g{0.5, 0.5, 0.5};
            for (int a = 0; a < mSmoke.dim; ++a) g[a] = (p[a] + (a == axis ? 0.0 : 0.5)) / scale;
            const double value = sampleFaceComponent(mAir, velocity, axis, g);
            // A non-finite velocity (a diverged run) moves nothing, as the other schemes'.
            u[std::size_t(face)] = std::isfinite(value) ? value : 0.0;
        });
    return u;
}

int ConservativeTransport::substeps(std::span<const double> u, double dt) const {
    double worst = 0.0;
    for (int z = 0; z < mSmoke.cells[2]; ++z)
        for (int y = 0; y < mSmoke.cells[1]; ++y)
            for (int x = 0; x < mSmoke.cells[0]; ++x) {
                double courant = 0.0;
                for (int a = 0; a < mSmoke.dim; ++a) {
                    const double lo = u[std::size_t(mSmoke.faceIndex(a, x, y, z))];
                    const double hi = u[std::size_t(mSmoke.upperFaceIndex(a, x, y, z))];
                    courant += std::max(std::abs(lo), std::abs(hi)) * dt / mSmoke.spacing[a];
                }
                worst = std::max(worst, courant);
            }
    return fluxSubsteps(worst);
}

double ConservativeTransport::advect(std::span<const double> u, double dt, int substeps,
                                     std::vector<double>& field,
                                     std::optional<OutsideAir::Field> which) const {
    const double h = dt / substeps;
    std::vector<double> flux(std::size_t(mSmoke.faceTotal()), 0.0);
    double crossed = 0.0;
    const auto at = [&](const std::array<int, 3>& c) {
        return std::size_t(mSmoke.cellIndex(c[0], c[1], c[2]));
    };
    // A neighbour `by` cells from c along axis, when it lies in the box and is fluid.
    const auto neighbour = [&](std::array<int, 3> c, int axis, int by, std::size_t& cell) {
        c[axis] += by;
        if (!mSmoke.periodic[axis] && (c[axis] < 0 || c[axis] >= mSmoke.cells[axis])) return false;
        c[axis] = mSmoke.wrap(axis, c[axis]);
        cell = at(c);
        return mMask[cell] != 0;
    };
    for (int step = 0; step < substeps; ++step) {
        for (int axis = 0; axis < mSmoke.dim; ++axis)
            forEachFace(mSmoke, axis, [&](std::int64_t face, const std::array<int, 3>& p) {
                const double velocity = u[std::size_t(face)];
                flux[std::size_t(face)] = 0.0;
                if (velocity == 0.0) return;
                // The cells below (−1) and above (0) the face, and the upwind one of them.
                const int upwind = velocity > 0.0 ? -1 : 0, downwind = velocity > 0.0 ? 0 : -1;
                std::size_t up = 0, down = 0, beyond = 0;
                const bool hasUp = neighbour(p, axis, upwind, up);
                const bool hasDown = neighbour(p, axis, downwind, down);
                double value;
                if (!hasUp) {  // the air comes in across a side
                    const int side = 2 * axis + (upwind == 0 ? 1 : 0);
                    value = mOutside.sides()[std::size_t(side)]
                                ? mOutside.value(mOutside.ghostIndex(side, p), which)
                                : field[down];
                } else {
                    const int away = velocity > 0.0 ? -2 : 1;
                    const double slope =
                        hasDown && neighbour(p, axis, away, beyond)
                            ? minmod(field[up] - field[beyond], field[down] - field[up])
                            : 0.0;
                    value = field[up] + 0.5 * slope;
                }
                flux[std::size_t(face)] = velocity * value;
                if (!hasUp || !hasDown) {  // a side face: what crosses it outwards
                    const double outwards = p[axis] == 0 ? -1.0 : 1.0;
                    crossed += outwards * velocity * value * h * mSmoke.cellVolume() /
                               mSmoke.spacing[axis];
                }
            });
        for (int z = 0; z < mSmoke.cells[2]; ++z)
            for (int y = 0; y < mSmoke.cells[1]; ++y)
                for (int x = 0; x < mSmoke.cells[0]; ++x) {
                    const std::size_t c = std::size_t(mSmoke.cellIndex(x, y, z));
                    if (!mMask[c]) continue;
                    double change = 0.0;
                    for (int a = 0; a < mSmoke.dim; ++a)
                        change += (flux[std::size_t(mSmoke.upperFaceIndex(a, x, y, z))] -
                                   flux[std::size_t(mSmoke.faceIndex(a, x, y, z))]) /
                                  mSmoke.spacing[a];
                    field[c] -= h * change;
                }
    }
    return crossed;
}

}  // namespace modeflow::reference
