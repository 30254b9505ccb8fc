#include "engine/simulation/ParticleEmission.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "engine/core/Error.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/simulation/ParticleMotion.h"

namespace modeflow {
namespace {

/// Fractions of a particle a rate's count is rounded up by: t accumulates dt step by step, and
/// 1500/s × 0.2 s must come to 300, not 299.99999999999997.
constexpr double kCountSlack = 1e-9;

/// SplitMix64's finalizer: a bijective mix of all 64 bits.
std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// A uniform number in [0, 1) for draw `draw` of particle `k` of set `set`, coordinate `axis`.
double uniform(std::uint64_t seed, std::size_t set, std::int64_t k, int draw, int axis) {
    std::uint64_t h = mix(seed);
    h = mix(h ^ std::uint64_t(set));
    h = mix(h ^ std::uint64_t(k));
    h = mix(h ^ (std::uint64_t(draw) << 2 | std::uint64_t(axis)));
    return double(h >> 11) * 0x1.0p-53;
}

/// A uniform point of the set's ball or box (z = 0 in 2D), or none when this draw of a ball's
/// enclosing cube falls outside it.
std::optional<Vec3> drawPoint(const ParticleSetSpec& spec, std::size_t set, std::int64_t k,
                              int draw, int dim) {
    Vec3 p{0.0, 0.0, 0.0}, u{0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) u[a] = uniform(spec.seed, set, k, draw, a);
    const ShapeSpec& region = spec.region;
    if (region.kind == ShapeKind::Box) {
        for (int a = 0; a < dim; ++a) p[a] = region.min[a] + u[a] * (region.max[a] - region.min[a]);
        return p;
    }
    double r2 = 0.0;
    for (int a = 0; a < dim; ++a) {
        u[a] = 2.0 * u[a] - 1.0;
        r2 += u[a] * u[a];
    }
    if (r2 > 1.0) return std::nullopt;
    for (int a = 0; a < dim; ++a) p[a] = region.center[a] + region.radius * u[a];
    return p;
}

}  // namespace

ParticleEmission::ParticleEmission(std::vector<ParticleSetSpec> sets, double shotEnd)
    : mSets(std::move(sets)), mShotEnd(shotEnd), mEmitted(mSets.size(), 0) {
    if (mSets.size() > std::size_t(maxParticleSets))
        throw Error("particles: " + std::to_string(mSets.size()) + " sets, at most " +
                    std::to_string(maxParticleSets));
    double total = 0.0;
    for (std::size_t s = 0; s < mSets.size(); ++s) {
        const ParticleSetSpec& set = mSets[s];
        total +=
            set.rate > 0.0
                ? std::floor(set.rate * std::max(0.0, std::min(set.end, mShotEnd) - set.start) +
                             kCountSlack)
                : double(set.count);
    }
    if (!(total <= double(maxParticles)))
        throw Error("particles: the sets emit " + std::to_string(std::llround(total)) +
                    " particles by the shot's end (t = " + std::to_string(mShotEnd) +
                    "), at most " + std::to_string(maxParticles) + " fit");
    mCapacity = std::int64_t(total);
}

std::int64_t ParticleEmission::emittedBy(std::size_t set, double t) const {
    const ParticleSetSpec& spec = mSets[set];
    if (!(t >= spec.start)) return 0;
    if (spec.rate <= 0.0) return spec.count;
    const double until = std::min({t, spec.end, mShotEnd});
    return std::int64_t(std::floor(spec.rate * std::max(0.0, until - spec.start) + kCountSlack));
}

std::size_t ParticleEmission::emit(double t, const MacGrid& smokeGrid,
                                   std::span<const std::uint8_t> fluidMask, Particles& particles) {
    const std::size_t before = particles.size();
    for (std::size_t s = 0; s < mSets.size(); ++s) {
        const std::int64_t target = emittedBy(s, t);
        std::vector<std::pair<std::int64_t, Vec3>> seeds;  // (smoke cell, place)
        for (std::int64_t k = mEmitted[s]; k < target; ++k) {
            std::optional<Vec3> seed;
            for (int draw = 0; draw < kMaxSeedDraws && !seed; ++draw) {
                seed = drawPoint(mSets[s], s, k, draw, smokeGrid.dim);
                if (seed && !inFluidCell(smokeGrid, fluidMask, *seed)) seed.reset();
            }
            if (!seed)
                throw Error("[[particles]] #" + std::to_string(s + 1) + ": " +
                            std::to_string(kMaxSeedDraws) + " draws in its " +
                            (mSets[s].region.kind == ShapeKind::Box ? "box" : "ball") +
                            " found no fluid cell: move it into the domain");
            seeds.emplace_back(cellOf(smokeGrid, *seed), *seed);
        }
        // In cell order: neighbours in space are neighbours in the buffers, so the device's
        // velocity reads of consecutive particles stay close (the draws stay the same).
        std::stable_sort(seeds.begin(), seeds.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [cell, seed] : seeds) {
            particles.position.insert(particles.position.end(), seed.begin(), seed.end());
            particles.velocity.insert(particles.velocity.end(), 3, 0.0);
            particles.set.push_back(std::uint8_t(s));
        }
        mEmitted[s] = std::max(mEmitted[s], target);
    }
    return particles.size() - before;
}

void ParticleEmission::restore(const Particles& particles) {
    requireParticleValues(particles);
    std::vector<std::int64_t> emitted(mSets.size(), 0);
    for (const std::uint8_t s : particles.set) {
        if (s >= mSets.size())
            throw Error("particles: a saved particle of set #" + std::to_string(s + 1) +
                        ", the scene has " + std::to_string(mSets.size()));
        ++emitted[s];
    }
    for (std::size_t s = 0; s < mSets.size(); ++s)
        if (emitted[s] > emittedBy(s, std::numeric_limits<double>::infinity()))
            throw Error("particles: " + std::to_string(emitted[s]) + " saved particles of set #" +
                        std::to_string(s + 1) + ", which emits " +
                        std::to_string(emittedBy(s, std::numeric_limits<double>::infinity())));
    mEmitted = std::move(emitted);
}

void requireParticleValues(const Particles& particles) {
    const std::size_t n = particles.size();
    if (particles.position.size() != 3 * n || particles.velocity.size() != 3 * n)
        throw Error("particles: " + std::to_string(n) + " particles with " +
                    std::to_string(particles.position.size()) + " position and " +
                    std::to_string(particles.velocity.size()) + " velocity values (3 each)");
    const auto finite = [](const double* values) {
        return std::isfinite(values[0]) && std::isfinite(values[1]) && std::isfinite(values[2]);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const double *x = &particles.position[3 * i], *v = &particles.velocity[3 * i];
        if (!particleLeft(x, v) && !(finite(x) && finite(v)))
            throw Error("particles: particle " + std::to_string(i) +
                        "'s position or velocity is not finite");
    }
}

std::int64_t cellOf(const MacGrid& smokeGrid, const Vec3& point) {
    std::array<int, 3> c{0, 0, 0};
    for (int a = 0; a < smokeGrid.dim; ++a) {
        const double x = (point[a] - smokeGrid.origin[a]) / smokeGrid.spacing[a];
        if (!std::isfinite(x)) return -1;
        const double n = smokeGrid.cells[a];
        const double cell =
            smokeGrid.periodic[a] ? x - n * std::floor(x / n) : std::clamp(x, 0.0, n - 1.0);
        c[a] = std::min(int(cell), smokeGrid.cells[a] - 1);
    }
    return smokeGrid.cellIndex(c[0], c[1], c[2]);
}

bool inFluidCell(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                 const Vec3& point) {
    const std::int64_t cell = cellOf(smokeGrid, point);
    return cell >= 0 && fluidMask[std::size_t(cell)] != 0;
}

}  // namespace modeflow
