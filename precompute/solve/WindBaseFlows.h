#pragma once
/// @file WindBaseFlows.h
/// The held flows a wind makes around [[domain]] walls (engine/README.md, "Wind"): per axis a and
/// direction ±, the potential flow B = ±e_a + ∇φ of a unit wind, with no flux through the walls
/// (cut-cell faces carry |face ∩ Ω|·B). The air enters through the upstream side at the wind's
/// speed, uniform over the side's fluid part, and leaves through the downstream side, where
/// φ = 0 (the potential's disturbance dies there, and the outflow takes whatever shape the walls
/// give it); along a periodic axis it wraps, and through the box's open sides ([grid] open, on
/// other axes) it may leave as the modes do (φ = 0 there too). A wind U blows as Σ_a |U_a| B_(a,
/// sign U_a): divergence-free in every cut cell, irrotational, tangent to the walls, and the
/// constant U in a whole box.

#include <vector>

#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellDec.h"
#include "precompute/dec/CutCellMeasures.h"

namespace modeflow {

/// 2·dim flows, entry 2a + 0 for a unit wind along +a (entering at the low side) and 2a + 1 along
/// −a: the face-normal velocity on every face of the complex (0 where the face has no fluid), in
/// CubicalComplex (= MacGrid) face numbering. An entry is empty where no such wind can blow: air
/// entering the upstream side with no way to the downstream one (walls between).
/// @throw modeflow::Error when a Poisson solve does not converge.
std::vector<std::vector<double>> windBaseFlows(const CubicalComplex& complex,
                                               const CutCellMeasures& measures,
                                               const CutCellDec& dec);

/// Per flow of windBaseFlows, the modal amplitudes c with B + Ψc the flow's Stokes flow within
/// the basis: the state viscosity relaxes a held flow's disturbance toward (engine/README.md,
/// "Wind"). ν Δ(B + Ψv) projected on the modes is −νΛv − ν Ψᵀ K B (K = velocityCurlCurl, the
/// wall's vorticity included at a no-slip wall), so v̇ = −νΛ(v − c) with c = −Λ⁻¹ Ψᵀ K B: B's
/// slip along a no-slip wall is vorticity the modes take up; a free-slip wall's potential flow is
/// irrotational, and c ≈ 0. Along a periodic axis c carries no flux (Qᵀc = 0, Q the modes'
/// fluxes through a cross-section): the wind's flux is held there as a pressure drop holds a
/// channel's. `modes` are ⋆-orthonormal fluxes on `dec`'s faces with `eigenvalues` Λ; a mode of
/// Λ = 0 gets 0 (K is semi-definite: KΨ = 0 there). An empty flow gets an empty entry.
std::vector<std::vector<double>> windStokesCorrections(
    const CubicalComplex& complex, const CutCellDec& dec, const Eigen::MatrixXd& modes,
    const Eigen::VectorXd& eigenvalues, const std::vector<std::vector<double>>& flows);

}  // namespace modeflow
