#pragma once
/// @file ExactSpectra.h
/// Closed-form Laplacian spectra of the unit disk and unit ball, the references of the
/// convergence study: roots of Bessel functions (cylindrical in 2D, spherical in 3D), each with
/// its multiplicity, in ascending order.

#include <vector>

namespace modeflow::validate {

enum class SpectrumKind {
    Velocity,   ///< divergence-free fields, no flux through the wall, free-slip (κ²)
    Neumann,    ///< scalars with no flux through the wall, constants left out (μ²)
    Dirichlet,  ///< scalars that vanish on the wall (μ²)
};

/// The first `count` eigenvalues of the unit disk (dim 2) or unit ball (dim 3).
/// 2D velocity: the stream function is a Dirichlet eigenfunction (free-slip: zero vorticity on
/// the wall), κ² = j_{m,n}². 3D velocity: toroidal fields, (x j_l(x))' = 0, and poloidal ones,
/// j_l(x) = 0, for l ≥ 1, each 2l + 1 times.
std::vector<double> unitBallSpectrum(int dim, SpectrumKind kind, int count);

}  // namespace modeflow::validate
