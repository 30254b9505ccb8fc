#pragma once
/// @file Combustion.h
/// Fire (a scene's `[fire]`, both backends' rule; the device's twin is shaders/fire_burn.comp
/// when it has one): after each step's advection and sources, the fuel of every fluid cell hotter
/// than the ignition temperature burns for the step at the fire's rate, first order,
///
///     dF/dt = −r F   ⇒   burned = F (1 − e^{−r dt}),
///
/// solved exactly, so no step is too long for it and the fuel never goes below 0; each unit
/// burned adds `heat` to the temperature and `smoke` to the density, and the flame field is the
/// fuel burned per unit time, burned / dt (the quantity renderers colour; 0 where nothing burns).
/// Fuel is conserved to round-off: what a cell loses is what its flame says times dt.

#include <cstdint>
#include <span>

#include "engine/core/SceneSpec.h"
#include "engine/simulation/SmokeFields.h"

namespace modeflow {

/// The fuel that burns in a cell holding `fuel` at `temperature` over dt.
double fuelBurned(const FireSpec& fire, double fuel, double temperature, double dt);

/// Burns the fuel of `fields` (which must carry fuel and flame) over dt in the fluid cells.
/// @throw modeflow::Error when the fields' sizes differ or dt is not positive and finite.
void burn(const FireSpec& fire, std::span<const std::uint8_t> fluidMask, double dt,
          SmokeFields& fields);

}  // namespace modeflow
