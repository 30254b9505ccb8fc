#include "engine/simulation/SmokeEmitter.h"

#include <string>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/core/RuntimeLimits.h"

namespace modeflow {

Vec3 SmokeEmitter::restCentre() const {
    switch (shape) {
        case EmitterShape::Box:
            return {0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1]), 0.5 * (min[2] + max[2])};
        case EmitterShape::Mesh:
            return {0.0, 0.0, 0.0};
        case EmitterShape::Ball:
            break;
    }
    return centre;
}

void requireEmitterCount(std::span<const SmokeEmitter> emitters) {
    if (emitters.size() > std::size_t(maxSmokeEmitters))
        throw Error("simulation: " + std::to_string(emitters.size()) + " sources, at most " +
                    std::to_string(maxSmokeEmitters));
}

SmokeEmitter SmokeEmitter::placedAt(double t) const {
    if (!moves()) return *this;
    ObstacleSpec motion;
    motion.path = path.empty() ? std::vector<std::pair<double, Vec3>>{{0.0, restCentre()}} : path;
    motion.rotation = rotation;
    SmokeEmitter placed = *this;
    placed.placement = MovingObstacle(motion).poseAt(t);
    return placed;
}

bool SmokeEmitter::contains(const Vec3& worldPoint, int dim) const {
    Vec3 point = worldPoint;
    if (placement) {
        // Into its rest pose: Rᵀ(x − c(t)) + c(rest).
        Eigen::Vector3d d;
        for (int a = 0; a < 3; ++a) d[a] = a < dim ? worldPoint[a] - placement->centre[a] : 0.0;
        const Eigen::Vector3d rest = placement->orientation.transpose() * d;
        const Vec3 centre = restCentre();
        for (int a = 0; a < 3; ++a) point[a] = a < dim ? rest[a] + centre[a] : worldPoint[a];
    }
    if (shape == EmitterShape::Mesh) {
        if (!levelSet) throw Error("a mesh source has no level set: attach it before the run");
        const double depth = levelSet->depthAt(point);
        return depth >= 0.0 && (thickness == 0.0 || depth <= thickness);
    }
    if (shape == EmitterShape::Box) {
        for (int a = 0; a < dim; ++a)
            if (point[a] < min[a] || point[a] > max[a]) return false;
        return true;
    }
    double distance2 = 0.0;
    for (int a = 0; a < dim; ++a) distance2 += (point[a] - centre[a]) * (point[a] - centre[a]);
    return distance2 <= radius * radius;
}

bool SmokeEmitter::contains(const Vec3& worldPoint, const MacGrid& grid) const {
    Vec3 middle = restCentre();
    if (shape == EmitterShape::Mesh && levelSet)
        for (int a = 0; a < 3; ++a)
            middle[a] = levelSet->origin[a] + 0.5 * (levelSet->samples[a] - 1) * levelSet->spacing;
    if (placement) middle = placement->centre;
    return contains(grid.nearestImage(worldPoint, middle), grid.dim);
}

SmokeEmitter emitterFromSource(const SourceSpec& source) {
    SmokeEmitter emitter;
    switch (source.shape.kind) {
        case ShapeKind::Ball:
            emitter.shape = EmitterShape::Ball;
            emitter.centre = source.shape.center;
            emitter.radius = source.shape.radius;
            break;
        case ShapeKind::Box:
            emitter.shape = EmitterShape::Box;
            emitter.min = source.shape.min;
            emitter.max = source.shape.max;
            break;
        case ShapeKind::Mesh:
            emitter.shape = EmitterShape::Mesh;
            emitter.thickness = source.thickness;
            break;
        default:
            throw Error(
                "[[source]] shape: smoke emitters are balls, boxes or meshes, got another shape");
    }
    emitter.densityRate = source.density;
    emitter.temperatureRate = source.temperature;
    emitter.fuelRate = source.fuel;
    emitter.start = source.start;
    emitter.end = source.end;
    emitter.velocity = source.velocity;
    emitter.path = source.path;
    emitter.rotation = source.rotation;
    return emitter;
}

std::vector<SmokeEmitter> activeEmitters(std::span<const SmokeEmitter> all, double t) {
    std::vector<SmokeEmitter> active;
    for (const SmokeEmitter& e : all)
        if (e.activeAt(t)) active.push_back(e.placedAt(t));
    return active;
}

void applyEmitters(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                   std::span<const SmokeEmitter> emitters, double dt, std::span<double> density,
                   std::span<double> temperature, std::span<double> fuel) {
    const std::size_t cells = std::size_t(smokeGrid.cellCount());
    if (fluidMask.size() != cells || density.size() != cells || temperature.size() != cells ||
        (!fuel.empty() && fuel.size() != cells))
        throw Error("applyEmitters: mask, density, temperature (and fuel) need " +
                    std::to_string(cells) + " values (one per smoke cell)");
    for (int z = 0; z < smokeGrid.cells[2]; ++z)
        for (int y = 0; y < smokeGrid.cells[1]; ++y)
            for (int x = 0; x < smokeGrid.cells[0]; ++x) {
                const std::int64_t c = smokeGrid.cellIndex(x, y, z);
                if (!fluidMask[c]) continue;
                const Vec3 centre{smokeGrid.cellCentre(0, x), smokeGrid.cellCentre(1, y),
                                  smokeGrid.cellCentre(2, z)};
                for (const SmokeEmitter& emitter : emitters)
                    if (emitter.contains(centre, smokeGrid)) {
                        density[c] += emitter.densityRate * dt;
                        temperature[c] += emitter.temperatureRate * dt;
                        if (!fuel.empty()) fuel[c] += emitter.fuelRate * dt;
                    }
            }
}

}  // namespace modeflow
