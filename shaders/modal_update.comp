#version 450
// The state updates of the modal integrators (README.md "Reduced dynamics"), float32, one workgroup over the
// N modes, or over MHD's state [v; F] (two parts of N at 0 and `stride`; r then holds
// [C(v, v); advect(v, F); C(F, F)] and the velocity part's R is the first minus the third). x is the state, y the point where r = R(y) was evaluated (modal_combine.comp), a = M y
// the weighted point modal_pair_sums.comp contracts next, f the modal force (constant over the
// step), M the diagonal mass (1 + alpha^2 kappa^2 for LANS-alpha), d the decay rates (nu kappa^2).
// As in engine/dynamics/ModalIntegrator.h the decay is Strang-split: x_i <- exp(-d_i h/2) x_i
// before (BEGIN) and after the step.
//
//   BEGIN         x <- exp(-d h/2) x;  y = x;  indirect arguments reset (live = full)
//   EXPLICIT      x <- exp(-d h/2) (x + h M^-1 (r + f))
//   RK4_STAGE s   k_s = M^-1 (r + f);  acc += w_s k_s (w = 1 2 2 1);  y = x + c_s h k_s (c = 1/2 1/2 1),
//                 after stage 3: x <- exp(-d h/2) (x + h/6 acc)
//   MIDPOINT      fixed point of seed eq. 6.8 in the midpoint ybar = (x + x')/2:
//                 y <- x + h/2 M^-1 (R(y) + f); when max|change| <= tolerance max|y| (or the change
//                 stalls at the round-off floor below 16 tolerance) the step has converged and the
//                 live indirect arguments are zeroed, so the remaining recorded iterations
//                 dispatch no work (no host round trip).
//   MIDPOINT_END  x <- exp(-d h/2) (2 y - x); an unconverged step keeps x (decay only)
//   TRAPEZOIDAL_START  r = R(x) kept in acc; y = x + h M^-1 (r + f), the explicit predictor
//   TRAPEZOIDAL   fixed point of seed eq. 6.9 in the end point y = x' (f constant over the step):
//                 y <- x + h/2 M^-1 (R(x) + R(y)) + h M^-1 f, converged as MIDPOINT
//   TRAPEZOIDAL_END  x <- exp(-d h/2) y; an unconverged step keeps x (decay only)
//
// Both fixed points converge when h |dR/dy| / 2 < 1 (the step's CFL-like number); the status block
// counts steps that reached the iteration limit so the host can report them.
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"

layout(local_size_x = 256, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) buffer State { float x[]; };
layout(std430, set = 0, binding = 1) buffer Point { float y[]; };
layout(std430, set = 0, binding = 2) buffer Weighted { float a[]; };
layout(std430, set = 0, binding = 3) readonly buffer Rhs { float r[]; };
layout(std430, set = 0, binding = 4) readonly buffer Force { float f[]; };
layout(std430, set = 0, binding = 5) readonly buffer Mass { float mass[]; };
layout(std430, set = 0, binding = 6) readonly buffer Decay { float decay[]; };
layout(std430, set = 0, binding = 7) buffer Accumulator { float acc[]; };
layout(std430, set = 0, binding = 8) buffer Status { ModalStatus status; };
layout(std430, set = 0, binding = 9) buffer Arguments { uint arguments[]; };
layout(push_constant) uniform Push { ModalUpdateParams params; };

shared float changeMax[gl_WorkGroupSize.x];
shared float sizeMax[gl_WorkGroupSize.x];

void setPoint(uint k, float value) {
    y[k] = value;
    a[k] = mass[k] * value;
}

void main() {
    const uint n = params.n;
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;
    const float h = params.h;
    const uint op = params.op;

    float change = 0.0, magnitude = 0.0;
    for (uint k = lane; k < params.parts * params.stride; k += size) {
        if (k % params.stride >= n) continue;  // padding between the parts
        const float halfDecay = exp(-0.5 * h * decay[k]);
        const float rk = params.lorentz != 0u && k < params.stride ? r[k] - r[2u * params.stride + k] : r[k];
        if (op == MODAL_OP_BEGIN) {
            x[k] *= halfDecay;
            setPoint(k, x[k]);
        } else if (op == MODAL_OP_EXPLICIT) {
            x[k] = halfDecay * (x[k] + h * (rk + f[k]) / mass[k]);
        } else if (op == MODAL_OP_RK4_STAGE) {
            const float slope = (rk + f[k]) / mass[k];
            const uint s = params.stage;
            acc[k] = (s == 0 ? 0.0 : acc[k]) + (s == 0 || s == 3 ? 1.0 : 2.0) * slope;
            if (s < 3) setPoint(k, x[k] + (s == 2 ? 1.0 : 0.5) * h * slope);
            else x[k] = halfDecay * (x[k] + h / 6.0 * acc[k]);
        } else if (op == MODAL_OP_MIDPOINT) {
            const float next = x[k] + 0.5 * h * (rk + f[k]) / mass[k];
            change = max(change, abs(next - y[k]));
            magnitude = max(magnitude, abs(next));
            setPoint(k, next);
        } else if (op == MODAL_OP_MIDPOINT_END) {
            // An iteration that did not converge may be diverging (h |dR/dv| / 2 > 1): keep the
            // state rather than step to a wild iterate; the host then takes smaller substeps.
            x[k] = halfDecay * (status.converged != 0u ? 2.0 * y[k] - x[k] : x[k]);
        } else if (op == MODAL_OP_TRAPEZOIDAL_START) {
            acc[k] = rk;
            setPoint(k, x[k] + h * (rk + f[k]) / mass[k]);
        } else if (op == MODAL_OP_TRAPEZOIDAL) {
            const float next = x[k] + (0.5 * h * (acc[k] + rk) + h * f[k]) / mass[k];
            change = max(change, abs(next - y[k]));
            magnitude = max(magnitude, abs(next));
            setPoint(k, next);
        } else if (op == MODAL_OP_TRAPEZOIDAL_END) {
            x[k] = halfDecay * (status.converged != 0u ? y[k] : x[k]);  // as MIDPOINT_END
        }
    }

    if (op == MODAL_OP_BEGIN && lane == 0) {
        status.iterations = 0;
        status.converged = 0;
        const uint words = 3 * params.argumentCount;
        for (uint e = 0; e < words; ++e) arguments[words + e] = arguments[e];
    }
    const bool ending = op == MODAL_OP_MIDPOINT_END || op == MODAL_OP_TRAPEZOIDAL_END;
    if (ending && lane == 0 && status.converged == 0) status.unconverged += 1;
    if (op != MODAL_OP_MIDPOINT && op != MODAL_OP_TRAPEZOIDAL) return;

    // Max-reduce the change and the size of y across the workgroup (any size, not only 2^k).
    changeMax[lane] = change;
    sizeMax[lane] = magnitude;
    barrier();
    for (uint stride = 1; stride < size; stride *= 2) {
        if (lane % (2 * stride) == 0 && lane + stride < size) {
            changeMax[lane] = max(changeMax[lane], changeMax[lane + stride]);
            sizeMax[lane] = max(sizeMax[lane], sizeMax[lane + stride]);
        }
        barrier();
    }
    if (lane == 0) {
        const float residual = sizeMax[0] > 0.0 ? changeMax[0] / sizeMax[0] : 0.0;
        // Converged at the tolerance, or at float32's round-off floor just above it: the change
        // no longer halves, so more iterations would only shuffle the last bits.
        const bool stalled = status.iterations > 0 && residual <= 16.0 * params.tolerance &&
                             residual > 0.5 * status.residual;
        status.iterations += 1;
        status.residual = residual;
        if (residual <= params.tolerance || stalled) {
            status.converged = 1;
            const uint words = 3 * params.argumentCount;
            for (uint e = 0; e < params.argumentCount; ++e) arguments[words + 3 * e] = 0;
        }
    }
}
