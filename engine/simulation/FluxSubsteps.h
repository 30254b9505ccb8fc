#pragma once
/// @file FluxSubsteps.h
/// How many forward Euler substeps a step of the conservative smoke transport takes (both
/// backends: reference::ConservativeTransport, device::ConservativeTransport): enough that
/// Σ_a |u_a| h / h_a ≤ ½ in every smoke cell, a TVD step of the MUSCL fluxes.

namespace modeflow {

/// The most substeps a step may take (a CFL of 2048 smoke cells a step).
inline constexpr int maxFluxSubsteps = 4096;

/// The substeps for `worstCourant`, the largest Σ_a max(|u| on the cell's two faces across a)
/// · dt / h_a over the smoke cells: ⌈2 · worst⌉, at least 1.
/// @throw modeflow::Error when that is more than maxFluxSubsteps (or the number is not finite).
int fluxSubsteps(double worstCourant);

}  // namespace modeflow
