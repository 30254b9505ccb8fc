/// @file InflowSection.cpp
/// `[[inflow]]`: a ball or box across a side the air crosses, through which the air coming in
/// carries a density, temperature and fuel of its own, and which may drive it (a jet through an
/// open wall, a smoke rake in a wind tunnel).

#include <algorithm>
#include <cmath>
#include <string>

#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {
namespace {

/// The side named by `side` of `s`, one the air comes in through: open, or the wind's upstream
/// side.
int readInflowSide(const TomlReader& reader, const Section& s, const SceneSpec& scene) {
    const toml::node* node = s.table.get("side");
    if (node == nullptr)
        reader.fail(s, "side", "missing required key (" + sideNames(scene.grid.dim) + ")",
                    &s.table);
    const std::optional<std::string> name = node->value<std::string>();
    const int side = name ? sideNamed(*name, scene.grid.dim) : -1;
    if (side < 0)
        reader.fail(s, "side",
                    "expected a side of the " + std::to_string(scene.grid.dim) +
                        "D box: " + sideNames(scene.grid.dim) + ", got " +
                        (name ? "\"" + *name + "\"" : describeType(*node)),
                    node);
    const int axis = side / 2;
    const bool high = side % 2 != 0;
    if (scene.grid.isPeriodic(axis))
        reader.fail(s, "side",
                    "\"" + *name + "\" lies across a periodic axis, whose ends are one plane " +
                        "with no side to let air in",
                    node);
    if (scene.grid.isOpen(axis, high)) return side;
    if (scene.wind && scene.wind->velocity[std::size_t(axis)] != 0.0) {
        const bool upstream = (scene.wind->velocity[std::size_t(axis)] < 0.0) == high;
        if (upstream) return side;
        reader.fail(s, "side",
                    "the wind leaves the box through " + *name + "; it comes in through " +
                        sideName(side ^ 1),
                    node);
    }
    reader.fail(s, "side",
                *name + " is a wall: open it ([grid] open = [\"" + *name +
                    "\"]) or let a [wind] blow in through it",
                node);
}

/// Whether the shape reaches across the plane of `side`, where its patch lies.
bool meetsSide(const ShapeSpec& shape, int side, const GridSpec& grid) {
    const int axis = side / 2;
    const double plane = side % 2 ? grid.boundsMax[axis] : grid.boundsMin[axis];
    if (shape.kind == ShapeKind::Ball) return std::abs(shape.center[axis] - plane) < shape.radius;
    return shape.min[axis] <= plane && plane <= shape.max[axis];
}

/// Whether the shape holds the centre of some smoke cell's face on `side` (where the air it lets
/// in comes through; the run checks the fluid's cells again): per axis along the side, the face
/// centres nearest the shape, any of them along a periodic axis. A hair of slack, so that a
/// centre on the shape's edge, which the run takes, is not refused here.
bool coversASmokeFace(const ShapeSpec& shape, int side, const SceneSpec& scene) {
    const GridSpec& grid = scene.grid;
    const int axis = side / 2;
    const double plane = side % 2 ? grid.boundsMax[axis] : grid.boundsMin[axis];
    const double across = shape.center[axis] - plane;
    double reach = shape.radius * shape.radius - across * across;
    for (int b = 0; b < grid.dim; ++b) {
        if (b == axis) continue;
        const int n = grid.resolution[b] * scene.smoke.resolutionScale;
        const double h = (grid.boundsMax[b] - grid.boundsMin[b]) / n;
        const double slack = 1e-9;
        // Centres lo + (k + ½) h, k in 0 … n − 1 (every k along a periodic axis).
        const auto inBox = [&](double k) {
            return grid.periodic[b] ? k : std::clamp(k, 0.0, double(n - 1));
        };
        if (shape.kind == ShapeKind::Box) {
            const double first =
                inBox(std::ceil((shape.min[b] - grid.boundsMin[b]) / h - 0.5 - slack));
            const double centre = grid.boundsMin[b] + (first + 0.5) * h;
            if (centre < shape.min[b] - slack * h || centre > shape.max[b] + slack * h)
                return false;
        } else {
            const double k = inBox(std::round((shape.center[b] - grid.boundsMin[b]) / h - 0.5));
            const double offset = grid.boundsMin[b] + (k + 0.5) * h - shape.center[b];
            reach -= offset * offset;
        }
    }
    return shape.kind == ShapeKind::Box || reach >= -1e-9 * shape.radius * shape.radius;
}

}  // namespace

InflowSpec readInflow(const TomlReader& reader, const toml::table& table, int index,
                      const SceneSpec& scene) {
    InflowSpec inflow;
    inflow.shape = readShape(reader, table, "[[inflow]]", index, ShapeUse::Inflow);
    const Section s{table, shapeEntryName("[[inflow]]", index, inflow.shape.kind)};
    inflow.side = readInflowSide(reader, s, scene);
    if (!meetsSide(inflow.shape, inflow.side, scene.grid))
        reader.fail(s, inflow.shape.kind == ShapeKind::Ball ? "center" : "min",
                    "the " + std::string(inflow.shape.kind == ShapeKind::Ball ? "ball" : "box") +
                        " does not reach across the plane of " + sideName(inflow.side) +
                        ", where the air it lets in comes through",
                    &table);
    if (!coversASmokeFace(inflow.shape, inflow.side, scene))
        reader.fail(s, inflow.shape.kind == ShapeKind::Ball ? "radius" : "max",
                    "where the " +
                        std::string(inflow.shape.kind == ShapeKind::Ball ? "ball" : "box") +
                        " meets " + sideName(inflow.side) +
                        " it holds the centre of no smoke cell's face there: make it larger",
                    &table);
    inflow.density = readSmokeValue(reader, s, "density", inflow.density, Sign::NonNegative);
    inflow.temperature = readSmokeValue(reader, s, "temperature", inflow.temperature);
    inflow.fuel = readSmokeValue(reader, s, "fuel", inflow.fuel, Sign::NonNegative);
    if (inflow.fuel > 0.0 && !scene.fire) reader.fail(s, "fuel", kFuelNeedsFire, table.get("fuel"));
    inflow.velocity = reader.vector(s, "velocity");
    if (inflow.velocity) {
        const Vec3& v = *inflow.velocity;
        const double speed = std::hypot(v[0], v[1], v[2]);  // no overflow in the squares
        if (!(speed <= kMaxInitialSpeed))
            reader.fail(s, "velocity",
                        "speed " + roughNumber(speed) + " is beyond " +
                            roughNumber(kMaxInitialSpeed) + " scene units per unit time",
                        table.get("velocity"));
    }
    inflow.start = reader.readNumber(s, "start", inflow.start, Sign::NonNegative);
    inflow.end = reader.readNumber(s, "end", inflow.end, Sign::Positive);
    if (inflow.end <= inflow.start)
        reader.fail(s, "end", "must be later than start (" + formatNumber(inflow.start) + ")",
                    table.get("end"));
    return inflow;
}

}  // namespace modeflow::scene
