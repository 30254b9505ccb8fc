#pragma once
/// @file InflowPatch.h
/// A scene's `[[inflow]]` at run time (engine/README.md, "Inflows"): where its ball or box meets
/// one of the box's sides the air coming in carries its density, temperature and fuel
/// (OutsideAir.h), and with a velocity its shape drives the air as a jet source's does
/// (SimulationSettings::velocityRegions). A plain value.

#include <optional>
#include <span>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "engine/simulation/SmokeEmitter.h"

namespace modeflow {

struct InflowPatch {
    int side = 0;  ///< 2·axis + (0 low, 1 high)
    /// Its shape (a ball or a box), start and end and velocity; it emits nothing itself.
    SmokeEmitter region;
    double density = 0.0;  ///< what the air it lets in carries
    double temperature = 0.0;
    double fuel = 0.0;
};

/// @throw modeflow::Error when its shape is not a ball or a box.
InflowPatch inflowFromSpec(const InflowSpec& spec);

/// The patches of `all` that let air in during the step starting at t.
std::vector<InflowPatch> activeInflows(std::span<const InflowPatch> all, double t);

/// Which inflows are on, remembered from step to step, so that a backend rebuilds what the air
/// coming in carries (OutsideAir's ghosts) only when one starts or stops.
class ActiveInflowSet {
public:
    /// Whether the patches of `all` on at t differ from those of the last call (the first call:
    /// always).
    bool changes(std::span<const InflowPatch> all, double t);

private:
    std::optional<std::vector<bool>> mOn;
};

}  // namespace modeflow
