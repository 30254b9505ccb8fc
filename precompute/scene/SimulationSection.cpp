/// @file SimulationSection.cpp
/// `[simulation]`: time step, integrator, dissipation, LANS-alpha or MHD, basis precision.

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

SimulationSpec readSimulation(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kSimulationKeys);
    SimulationSpec sim;
    sim.dt = reader.readNumber(s, "dt", sim.dt, Sign::Positive);
    sim.integrator =
        reader.readChoice(s, "integrator", sim.integrator, Choices<Integrator>(kIntegrators));
    sim.viscosity = reader.readNumber(s, "viscosity", sim.viscosity, Sign::NonNegative);
    sim.alpha = reader.readNumber(s, "alpha", sim.alpha, Sign::NonNegative);
    sim.halfPrecisionBasis = reader.readChoice(s, "basis_precision", sim.halfPrecisionBasis,
                                               Choices<bool>(kBasisPrecisions));
    if (const toml::node* node = s.table.get("mhd")) {
        const auto* flag = node->as_boolean();
        if (flag == nullptr)
            reader.fail(s, "mhd", "expected true or false, got " + describeType(*node), node);
        sim.mhd = flag->get();
    }
    sim.magneticDiffusivity =
        reader.readNumber(s, "magnetic_diffusivity", sim.magneticDiffusivity, Sign::NonNegative);
    if (sim.mhd && sim.alpha > 0.0)
        reader.fail(s, "alpha", "LANS-alpha and MHD cannot be combined (set one of them)",
                    s.table.get("alpha"));
    if (sim.mhd && sim.integrator == Integrator::Linearized)
        reader.fail(s, "integrator",
                    "linearized is for fluids; MHD takes midpoint (or trapezoidal, explicit, rk4)",
                    s.table.get("integrator"));
    if (!sim.mhd && s.table.contains("magnetic_diffusivity"))
        reader.fail(s, "magnetic_diffusivity", "only used with mhd = true",
                    s.table.get("magnetic_diffusivity"));
    return sim;
}

}  // namespace modeflow::scene
