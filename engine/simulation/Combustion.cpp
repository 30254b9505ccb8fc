#include "engine/simulation/Combustion.h"

#include <cmath>
#include <string>

#include "engine/core/Error.h"

namespace modeflow {

double fuelBurned(const FireSpec& fire, double fuel, double temperature, double dt) {
    if (!(temperature > fire.ignition) || !(fuel > 0.0)) return 0.0;
    // 1 − e^{−x} without the cancellation of a small x.
    return fuel * -std::expm1(-fire.burnRate * dt);
}

void burn(const FireSpec& fire, std::span<const std::uint8_t> fluidMask, double dt,
          SmokeFields& fields) {
    const std::size_t cells = fluidMask.size();
    if (fields.density.size() != cells || fields.temperature.size() != cells ||
        fields.fuel.size() != cells || fields.flame.size() != cells)
        throw Error("burn: density, temperature, fuel and flame need " + std::to_string(cells) +
                    " values (one per smoke cell)");
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw Error("burn: the step " + std::to_string(dt) + " is not positive and finite");
    for (std::size_t c = 0; c < cells; ++c) {
        const double burned =
            fluidMask[c] ? fuelBurned(fire, fields.fuel[c], fields.temperature[c], dt) : 0.0;
        fields.fuel[c] -= burned;
        fields.temperature[c] += fire.heat * burned;
        fields.density[c] += fire.smoke * burned;
        fields.flame[c] = burned / dt;
    }
}

}  // namespace modeflow
