#include "engine/simulation/InflowPatch.h"

#include "engine/core/Error.h"

namespace modeflow {

InflowPatch inflowFromSpec(const InflowSpec& spec) {
    if (spec.shape.kind != ShapeKind::Ball && spec.shape.kind != ShapeKind::Box)
        throw Error("an inflow is a ball or a box");
    // Its region is a source of that shape that drives the air and adds nothing.
    SourceSpec source;
    source.shape = spec.shape;
    source.density = 0.0;
    source.start = spec.start;
    source.end = spec.end;
    source.velocity = spec.velocity;
    return {spec.side, emitterFromSource(source), spec.density, spec.temperature, spec.fuel};
}

std::vector<InflowPatch> activeInflows(std::span<const InflowPatch> all, double t) {
    std::vector<InflowPatch> active;
    for (const InflowPatch& patch : all)
        if (patch.region.activeAt(t)) active.push_back(patch);
    return active;
}

bool ActiveInflowSet::changes(std::span<const InflowPatch> all, double t) {
    std::vector<bool> on(all.size());
    for (std::size_t i = 0; i < on.size(); ++i) on[i] = all[i].region.activeAt(t);
    if (mOn == on) return false;
    mOn = std::move(on);
    return true;
}

}  // namespace modeflow
