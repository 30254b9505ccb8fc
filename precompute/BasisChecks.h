#pragma once
/// @file BasisChecks.h
/// Independent checks of a cached basis, recomputed from the stored data (not trusted from the
/// solver): divergence of every velocity mode and orthonormality of both bases.
///
/// A closed-form basis stores descriptors, not columns: its modes are materialized for the check,
/// all of them when faces × modes² is at most kFullCheckWork, else a sample of them (see
/// checkedModes), so that inspecting 10 000 modes on a 64³ box takes seconds, not hours.

#include <cstdint>
#include <vector>

#include "engine/format/BasisCache.h"

namespace modeflow {

struct BasisChecks {
    double maxDivergence = 0.0;           ///< max over modes of |dΨ|∞ / |Ψ|∞
    double velocityOrthonormality = 0.0;  ///< max |ΨᵀM Ψ − I|
    double scalarOrthonormality = 0.0;    ///< max |ΦᵀM Φ − I|
    int velocityChecked = 0;              ///< velocity modes the checks covered
    int scalarChecked = 0;                ///< scalar modes the checks covered
};

/// Above this many multiply-adds (DOFs × checked modes²) a closed-form basis is sampled.
inline constexpr double kFullCheckWork = 2e9;

/// The positions (0-based) of the modes checked among `count` on `dofs` DOFs: all, or 48
/// positions spread evenly over the basis, each with its successor (the other polarization or
/// phase of the same wave vector, which the Gram matrix must find orthogonal).
std::vector<int> checkedModes(std::int64_t dofs, int count);

BasisChecks checkBasis(const BasisCache& cache);

}  // namespace modeflow
