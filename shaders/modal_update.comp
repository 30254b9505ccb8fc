#version 450
// The state updates of the modal integrators (engine/README.md "Reduced dynamics"), float32, one workgroup over the
// N modes, or over MHD's state [v; F] (two parts of N at 0 and `stride`; r then holds
// [C(v, v); advect(v, F); C(F, F)] and the velocity part's R is the first minus the third). x is the state, y the point where r = R(y) was evaluated (modal_combine.comp), a = M y
// the weighted point modal_pair_sums.comp contracts next, f the modal force (constant over the
// step), M the diagonal mass (1 + alpha^2 kappa^2 for LANS-alpha), d the decay rates (nu kappa^2).
// As in engine/dynamics/ModalIntegrator.h the decay is Strang-split: x_i <- exp(-d_i h/2) x_i
// before (BEGIN) and after the step; below, exp(-d h/2) v stands for t + exp(-d h/2) (v - t),
// t what the value decays toward (0 but in a wind round [[domain]] walls).
//
//   BEGIN         x <- exp(-d h/2) x;  y = x, or for a midpoint step after converged implicit
//                 steps the warm start y = x + h/2 M^-1 (R~ + f) (see main());
//                 indirect arguments reset (live = full)
//   EXPLICIT      x <- exp(-d h/2) (x + h M^-1 (r + f))
//   RK4_STAGE s   k_s = M^-1 (r + f);  acc += w_s k_s (w = 1 2 2 1);  y = x + c_s h k_s (c = 1/2 1/2 1),
//                 after stage 3: x <- exp(-d h/2) (x + h/6 acc)
//   MIDPOINT      fixed point of seed eq. 6.8 in the midpoint ybar = (x + x')/2:
//                 y <- x + h/2 M^-1 (R(y) + f), Anderson-accelerated (iterate() below); when
//                 max|change| <= tolerance max|y| (or the change stalls at the round-off floor
//                 below 16 tolerance) the step has converged and the
//                 live indirect arguments are zeroed, so the remaining recorded iterations
//                 dispatch no work (no host round trip).
//   MIDPOINT_END  x <- exp(-d h/2) (2 y - x); an unconverged step keeps x (decay only)
//   TRAPEZOIDAL_START  r = R(x) kept in acc; y = x + h M^-1 (r + f), the explicit predictor
//   TRAPEZOIDAL   fixed point of seed eq. 6.9 in the end point y = x' (f constant over the step):
//                 y <- x + h/2 M^-1 (R(x) + R(y)) + h M^-1 f, converged as MIDPOINT
//   TRAPEZOIDAL_END  x <- exp(-d h/2) y; an unconverged step keeps x (decay only)
//   LINEARIZED_START  y = x + h/2 (g + M^-1 f), a = M y, the predictor x~ whose pair sums the
//                 linearized rule's iterations keep (engine/dynamics/ModalIntegrator.h): g the
//                 rate held from the last step (history slot 2m + 3), or without one g = M^-1 r,
//                 r = R(x) evaluated by the dispatches before (which BEGIN switches off through
//                 their indirect arguments while a rate is held)
//   MIDPOINT with `frozen`: the same map with r = L(x~) y, a left as it is (a linear fixed point)
//   LINEARIZED_END  as MIDPOINT_END; a converged step holds its rate g = 2 (y - x)/h - M^-1 f
//
// Plainly iterated, both fixed points converge when h |dR/dy| / 2 < 1 (the step's CFL-like number),
// accelerated often beyond; the status block counts steps that reached the iteration limit so the
// host can report them.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "ModalStepParams.h"

layout(local_size_x = 256, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) buffer State { float x[]; };
layout(std430, set = 0, binding = 1) buffer Point { float y[]; };
layout(std430, set = 0, binding = 2) buffer Weighted { float a[]; };
layout(std430, set = 0, binding = 3) readonly buffer Rhs { float r[]; };
layout(std430, set = 0, binding = 4) readonly buffer Force { float f[]; };
layout(std430, set = 0, binding = 5) readonly buffer Mass { float mass[]; };
// The decay rates d, then (from parts * stride on) what each value decays toward: 0, or a
// wind's held flow's Stokes correction (engine/dynamics/FluidSystem.h).
layout(std430, set = 0, binding = 6) readonly buffer Decay { float decay[]; };
layout(std430, set = 0, binding = 7) buffer Accumulator { float acc[]; };
layout(std430, set = 0, binding = 8) buffer Status { ModalStatus status; };
layout(std430, set = 0, binding = 9) buffer Arguments { uint arguments[]; };
// The implicit iterations' history (Anderson acceleration, see iterate).
layout(std430, set = 0, binding = 10) buffer History { float history[]; };
// 1 / mass, and 0 for the modes [forcing] holds: their rates are 0, so they keep their amplitude
// (their decay rates are 0 too) while their weighted values a = M y still act on the others.
layout(std430, set = 0, binding = 11) readonly buffer InverseMass { float inverseMass[]; };
layout(push_constant) uniform Push { ModalUpdateParams params; };
// What a dispatch does, fixed at compile time, one pipeline each (engine/device/ModalKernels):
// lavapipe runs every branch of an `if`, loads included, whichever lanes take it, so with the
// operation a run-time value every dispatch ran every operation's loads (each operation faster
// apart on lavapipe: precompute/README.md "Closed-form bases").
layout(constant_id = 1) const uint OP = MODAL_OP_BEGIN;  // MODAL_OP_*
layout(constant_id = 2) const bool FROZEN = false;  // MIDPOINT of a linearized step: a left alone
layout(constant_id = 3) const bool LORENTZ = false; // MHD: r's velocity part less C(F, F)

// Subgroup partial sums, then their sums: SUMS values per iteration (see iterate).
#define MAX_SUBGROUPS 64
#define SUMS (2 + ANDERSON_DEPTH * (ANDERSON_DEPTH + 1) / 2 + ANDERSON_DEPTH)
shared float partial[MAX_SUBGROUPS][SUMS];
shared float solution[ANDERSON_DEPTH];

void setPoint(uint k, float value) {
    y[k] = value;
    if (!FROZEN) a[k] = mass[k] * value;
}

// Not padding after a part (at most two parts; no modulo: lavapipe divides lane by lane).
bool inState(uint k) { return k < params.stride ? k < params.n : k - params.stride < params.n; }

// R(y)_k from r (MHD with the Lorentz force: the velocity part less C(F, F)).
float rhs(uint k) {
    return LORENTZ && k < params.stride ? r[k] - r[2u * params.stride + k] : r[k];
}

// The midpoint rule's fixed-point map g(y)_k with r = R(y) (see the header).
float midpointMap(uint k) { return x[k] + 0.5 * params.h * (rhs(k) + f[k]) * inverseMass[k]; }

// The fixed-point map g(y)_k of the implicit rules (see the header).
float fixedPointMap(uint k) {
    if (OP == MODAL_OP_MIDPOINT) return midpointMap(k);
    return x[k] + (0.5 * params.h * (acc[k] + rhs(k)) + params.h * f[k]) * inverseMass[k];
}

// Entry k of history vector `slot` (history layout: see iterate).
uint at(uint slot, uint k) { return slot * params.parts * params.stride + k; }
#define HELD_RATE_SLOT (2u * ANDERSON_DEPTH + 3u)

// The workgroup's sums of `values` (max for the first two), in partial[0] after the call.
void reduceWorkgroup(float values[SUMS]) {
    float reduced[SUMS];
    reduced[0] = subgroupMax(values[0]);
    reduced[1] = subgroupMax(values[1]);
    for (int v = 2; v < SUMS; ++v) reduced[v] = subgroupAdd(values[v]);
    if (subgroupElect())
        for (int v = 0; v < SUMS; ++v) partial[gl_SubgroupID][v] = reduced[v];
    barrier();
    if (gl_LocalInvocationID.x == 0) {
        for (uint g = 1; g < gl_NumSubgroups; ++g) {
            partial[0][0] = max(partial[0][0], partial[g][0]);
            partial[0][1] = max(partial[0][1], partial[g][1]);
            for (int v = 2; v < SUMS; ++v) partial[0][v] += partial[g][v];
        }
    }
    barrier();
}

// Solves (D^T D) c = D^T F for the `used` columns of the history (Gram entries and right-hand
// side from partial[0]) by Cholesky, into solution[]; a column whose pivot falls below 1e-6 of
// its diagonal (nearly dependent on the later ones) is dropped (its coefficient 0).
void solveLeastSquares(uint used) {
    float l[ANDERSON_DEPTH][ANDERSON_DEPTH];
    float z[ANDERSON_DEPTH];
    bool kept[ANDERSON_DEPTH];
    int e = 2;
    for (int i = 0; i < ANDERSON_DEPTH; ++i)
        for (int j = 0; j <= i; ++j) l[i][j] = partial[0][e++];
    for (int i = 0; i < ANDERSON_DEPTH; ++i) z[i] = partial[0][e++];
    for (int i = 0; i < ANDERSON_DEPTH; ++i) {
        kept[i] = false;
        solution[i] = 0.0;
        if (i >= int(used)) continue;
        float d = l[i][i];
        for (int k = 0; k < i; ++k) d -= l[i][k] * l[i][k];
        if (!(d > 1e-6 * l[i][i])) {
            for (int k = 0; k < i; ++k) l[i][k] = 0.0;
            continue;
        }
        kept[i] = true;
        l[i][i] = sqrt(d);
        for (int j = i + 1; j < int(used); ++j) {
            float v = l[j][i];
            for (int k = 0; k < i; ++k) v -= l[j][k] * l[i][k];
            l[j][i] = v / l[i][i];
        }
        for (int k = 0; k < i; ++k) z[i] -= l[i][k] * z[k];
        z[i] /= l[i][i];
    }
    for (int i = int(used) - 1; i >= 0; --i) {
        if (!kept[i]) { z[i] = 0.0; continue; }
        for (int k = i + 1; k < int(used); ++k) z[i] -= l[k][i] * z[k];
        z[i] /= l[i][i];
        solution[i] = z[i];
    }
}

// One implicit iteration, Anderson-accelerated (Walker & Ni 2011, depth m = ANDERSON_DEPTH): with
// the map's values g_i = g(y_i) and residuals F_i = g_i - y_i of the last iterations, and the
// columns D_i = F_{i+1} - F_i, E_i = g_{i+1} - g_i of the last m,
//     c = argmin |F_m - D c|,   y_{m+1} = g_m - E c,
// a GMRES-like step over the last m directions. Plain iteration contracts by the step's
// h |dR/dy| / 2 per iteration, and that Jacobian of the advection term has nearly imaginary
// eigenvalues: close to 1 (an energetic flow at a large step) plain iteration takes dozens of
// iterations and a one-direction secant hardly helps, where m directions cut them several fold
// (ModalStepKernelTest; engine/README.md "Vulkan runtime"). The first iteration of a step is the plain
// one. Converged when max|F| <= tolerance max|g|. History (binding 10): D in slots 0..m-1, E in
// m..2m-1, the last F and g in 2m and 2m + 1, the warm start's r_before in 2m + 2 (main()), the
// linearized rule's held rate in 2m + 3, each parts * stride floats.
void iterate(uint lane, uint size) {
    const uint m = ANDERSON_DEPTH;
    const float infinity = uintBitsToFloat(0x7f800000u);
    const uint iteration = status.iterations;
    const bool accelerated = params.anderson != 0u && iteration > 0u;
    const uint slot = accelerated ? (iteration - 1u) % m : 0u;
    const uint used = accelerated ? min(iteration, m) : 0u;
    float sums[SUMS];
    for (int v = 0; v < SUMS; ++v) sums[v] = 0.0;
    for (uint k = lane; k < params.parts * params.stride; k += size) {
        if (!inState(k)) continue;
        const float g = fixedPointMap(k);
        const float residual = g - y[k];
        // A non-finite iterate (a step whose R overflows, or diverging iterates) must never count
        // as converged, but max() may return its other operand for a NaN: it enters as infinity.
        sums[0] = max(sums[0], isnan(residual) ? infinity : abs(residual));
        sums[1] = max(sums[1], abs(g));
        if (accelerated) {
            history[at(slot, k)] = residual - history[at(2u * m, k)];
            history[at(m + slot, k)] = g - history[at(2u * m + 1u, k)];
            float column[ANDERSON_DEPTH];
            for (uint i = 0; i < m; ++i) column[i] = i < used ? history[at(i, k)] : 0.0;
            int e = 2;
            for (uint i = 0; i < m; ++i)
                for (uint j = 0; j <= i; ++j) sums[e++] += column[i] * column[j];
            for (uint i = 0; i < m; ++i) sums[e++] += column[i] * residual;
        }
        history[at(2u * m, k)] = residual;
        history[at(2u * m + 1u, k)] = g;
    }
    reduceWorkgroup(sums);
    if (lane == 0 && accelerated) solveLeastSquares(used);
    barrier();
    for (uint k = lane; k < params.parts * params.stride; k += size) {
        if (!inState(k)) continue;
        float next = history[at(2u * m + 1u, k)];
        for (uint i = 0; i < used; ++i) next -= solution[i] * history[at(m + i, k)];
        setPoint(k, next);
    }
    if (lane != 0) return;
    // Relative to max|g|, or absolute where every |g| is 0 (or NaN, which max() may drop).
    const float residual = partial[0][1] > 0.0 ? partial[0][0] / partial[0][1] : partial[0][0];
    // Converged at the tolerance, or at float32's round-off floor just above it: the change
    // no longer halves, so more iterations would only shuffle the last bits.
    const bool stalled = iteration > 0 && residual <= 16.0 * params.tolerance &&
                         residual > 0.5 * status.residual;
    status.iterations += 1;
    status.residual = residual;
    if (residual <= params.tolerance || stalled) {
        status.converged = 1;
        const uint words = 3 * params.argumentCount;
        for (uint e = 0; e < params.argumentCount; ++e) arguments[words + 3 * e] = 0;
    }
}

void main() {
    const uint n = params.n;
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;
    const float h = params.h;
    const uint op = OP;
    if (op == MODAL_OP_MIDPOINT || op == MODAL_OP_TRAPEZOIDAL) {
        iterate(lane, size);
        return;
    }

    // Warm start of a midpoint step: R at its midpoint extrapolated in time from the R the last
    // converged implicit steps ended with (r, and history slot 2m + 2: the one before), R~ =
    // 2 r - r_before, or r after one such step; y = g with R~ is then within h/2 |R~ - R(y*)| =
    // O(h^3) of the fixed point (O(h^2) after one step), where the first plain iterate from
    // y = x, which costs an evaluation, is O(h^2) off. 64^3 box, N = 1000: 6 -> 4 evaluations a
    // step (precompute/README.md "Closed-form bases").
    const uint held = op == MODAL_OP_BEGIN ? status.heldRhs : 0u;
    const bool warm = params.warm != 0u && held != 0u;
    for (uint k = lane; k < params.parts * params.stride; k += size) {
        if (!inState(k)) continue;
        const float halfDecay = exp(-0.5 * h * decay[k]);
        const float target = decay[params.parts * params.stride + k];
        const float rk = rhs(k);
        if (op == MODAL_OP_BEGIN) {
            x[k] = target + halfDecay * (x[k] - target);
            const uint before = at(2u * ANDERSON_DEPTH + 2u, k);
            const float extrapolated = held >= 2u ? 2.0 * rk - history[before] : rk;
            setPoint(k, warm ? x[k] + 0.5 * h * (extrapolated + f[k]) * inverseMass[k] : x[k]);
            if (held >= 1u) history[before] = rk;
        } else if (op == MODAL_OP_EXPLICIT) {
            x[k] = target + halfDecay * (x[k] + h * (rk + f[k]) * inverseMass[k] - target);
        } else if (op == MODAL_OP_RK4_STAGE) {
            const float slope = (rk + f[k]) * inverseMass[k];
            const uint s = params.stage;
            acc[k] = (s == 0 ? 0.0 : acc[k]) + (s == 0 || s == 3 ? 1.0 : 2.0) * slope;
            if (s < 3) setPoint(k, x[k] + (s == 2 ? 1.0 : 0.5) * h * slope);
            else x[k] = target + halfDecay * (x[k] + h / 6.0 * acc[k] - target);
        } else if (op == MODAL_OP_LINEARIZED_START) {
            const float rate = status.heldRate != 0u ? history[at(HELD_RATE_SLOT, k)] : rk * inverseMass[k];
            setPoint(k, x[k] + 0.5 * h * (rate + f[k] * inverseMass[k]));
        } else if (op == MODAL_OP_MIDPOINT_END || op == MODAL_OP_LINEARIZED_END) {
            if (op == MODAL_OP_LINEARIZED_END)
                history[at(HELD_RATE_SLOT, k)] = 2.0 * (y[k] - x[k]) / h - f[k] * inverseMass[k];
            // An iteration that did not converge may be diverging (h |dR/dv| / 2 > 1): keep the
            // state rather than step to a wild iterate; the host then takes smaller substeps.
            x[k] = target + halfDecay * ((status.converged != 0u ? 2.0 * y[k] - x[k] : x[k]) - target);
        } else if (op == MODAL_OP_TRAPEZOIDAL_START) {
            acc[k] = rk;
            setPoint(k, x[k] + h * (rk + f[k]) * inverseMass[k]);
        } else if (op == MODAL_OP_TRAPEZOIDAL_END) {
            x[k] = target + halfDecay * ((status.converged != 0u ? y[k] : x[k]) - target);  // as MIDPOINT_END
        }
    }

    // r is about to hold R of an explicit stage: no step-end R is held any more.
    if ((op == MODAL_OP_EXPLICIT || op == MODAL_OP_RK4_STAGE) && lane == 0) status.heldRhs = 0;
    if (op == MODAL_OP_BEGIN && lane == 0) {
        status.iterations = 0;
        status.converged = 0;
        const uint words = 3 * params.argumentCount;
        for (uint e = 0; e < words; ++e) arguments[words + e] = arguments[e];
        // The linearized predictor's R(x): not evaluated while a rate is held.
        const uint predictor = 2u * words, predictorWords = 3 * params.predictorCount;
        for (uint e = 0; e < predictorWords; ++e)
            arguments[predictor + predictorWords + e] =
                status.heldRate != 0u && e % 3u == 0u ? 0u : arguments[predictor + e];
    }
    const bool ending = op == MODAL_OP_MIDPOINT_END || op == MODAL_OP_TRAPEZOIDAL_END ||
                        op == MODAL_OP_LINEARIZED_END;
    if (ending && lane == 0) {
        if (status.converged == 0) status.unconverged += 1;
        // A linearized step ends with r = L(x~) y, not R at the step's end: nothing to extrapolate.
        const bool holds = status.converged != 0u && op != MODAL_OP_LINEARIZED_END;
        status.heldRhs = holds ? min(status.heldRhs + 1u, 2u) : 0u;
        status.heldRate = op == MODAL_OP_LINEARIZED_END && status.converged != 0u && h != 0.0 ? 1u : 0u;
    }
}
