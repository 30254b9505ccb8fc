#pragma once
/// @file BasisChecks.h
/// Independent checks of a cached basis, recomputed from the stored data (not trusted from the
/// solver): divergence of every velocity mode and orthonormality of both bases.

#include "engine/format/BasisCache.h"

namespace modeflow {

struct BasisChecks {
    double maxDivergence = 0.0;             ///< max over modes of |dΨ|∞ / |Ψ|∞
    double velocityOrthonormality = 0.0;    ///< max |ΨᵀM Ψ − I|
    double scalarOrthonormality = 0.0;      ///< max |ΦᵀM Φ − I|
};

BasisChecks checkBasis(const BasisCache& cache);

}  // namespace modeflow
