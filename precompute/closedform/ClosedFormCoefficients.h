#pragma once
/// @file ClosedFormCoefficients.h
/// The structural coefficients of a closed-form basis (engine/format/SeparableModes.h), exactly
/// the quadrature of precompute/coefficients/CoefficientAssembly.h on its materialized modes, but
/// assembled entry by entry from selection rules in O(non-zeros) time and memory.
///
/// At an edge along a (2D: a vertex, a = z), with b, c the next axes, every quantity of the
/// quadrature is separable: with σ_d = (2/h_d) sin(θ_d/2) and γ_d = cos(θ_d/2) (the mean of a
/// half-position factor over its two neighbours is γ_d times the factor at the whole position),
///   ω_i  = (A^i_b σ^i_c − A^i_c σ^i_b) s^i_b s^i_c f^i_a,
///   u_kb = A^k_b γ^k_c s^k_b f^k_c f^k_a,      u_jc = A^j_c γ^j_b f^j_b s^j_c f^j_a,
/// so C[k][i][j] = |cell| Σ_a (A^i_b σ^i_c − A^i_c σ^i_b) Σ_a(f f f) ×
///   [A^k_b γ^k_c A^j_c γ^j_b Σ_b(s^i s^k f^j) Σ_c(s^i f^k s^j) − (k ↔ j in the last bracket)],
/// each Σ_d a 1-D sum over the positions of axis d. A 1-D sum of three factors is, by
/// product-to-sum, (n/4) Σ_± cos(...) over the sign choices whose wave numbers l^i ± l^k ± l^j
/// vanish mod 2n (wall: the sum is half of one over the full period 2n, the summand being even)
/// or mod n (periodic); the cosines are of multiples of π/2, so every 1-D sum is an exact
/// multiple of n/4. That is the selection rule: C[k][i][j] = 0 unless the wave vectors of i, k,
/// j close a triangle per axis modulo the period.

#include <vector>

#include "engine/format/BasisCache.h"

namespace modeflow {

/// The sparse k < j entries of C for `modes` on `grid` (every entry whose terms do not cancel to
/// round-off, |C| > 1e-12 of its largest term), in a fixed order. Cost: a few table look-ups per
/// pair of wave vectors and a few dozen operations per non-zero.
BasisCache::Coefficients assembleClosedFormCoefficients(const GridSpec& grid,
                                                        const std::vector<SeparableMode>& modes);

/// The non-zeros the first `modes` modes of a box give, for memory estimates, a little above the
/// counts measured on 64³ and 256² boxes: 2D 1.2 N² (measured 1.03–1.13 N² at N = 200…2000); 3D
/// (2.35 + 0.55 log10(N/1000)) N², at least 1.5 N² (measured 2.09, 2.24, 2.43, 2.58, 2.76 N² at
/// N = 600, 1000, 2000, 4000, 10 000; a few percent more on periodic axes, where both phases of a
/// wave vector interact).
double estimatedClosedFormNonZeros(int dim, int modes);

/// Bytes of one stored non-zero in a cache (k, i, j as int32 and the value).
inline constexpr double kSparseEntryBytes = 20.0;

}  // namespace modeflow
