#version 450
// One step of the dye on a surface in its scalar basis (engine/device/SurfaceDye.h; CPU
// reference engine/surface/SurfaceDye.cpp): with K = A(v) antisymmetric (surface_dye_pairs.comp)
// and a = h/2, the midpoint (Cayley) step
//
//     (I + a K) f' = (I - a K) f + h s,        mean' = mean + h s_0,
//
// keeps |f| when s = 0, as the CPU's does. One workgroup solves it: I + aK is not symmetric, but
// (I - aK)(I + aK) = I - a^2 K^2 = I + a^2 K^T K is symmetric positive definite, so conjugate
// gradients on these normal equations converge for any step (in at most about M/2 iterations:
// the eigenvalues +-i s of K give the same 1 + a^2 s^2), from f, the best guess there is. K is
// unpacked once into `work` as a dense M x M matrix beside the iteration's vectors (any M fits),
// read by columns in each product so that the lanes (rows) read consecutive words; the dot
// products are reduced in shared memory; every branch and loop bound is uniform.
#extension GL_GOOGLE_include_directive : require
#include "SurfaceDyeParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Pairs { float pairs[]; };
layout(std430, set = 0, binding = 1) buffer State { float state[]; };  // [mean, f_1 ... f_M]
layout(std430, set = 0, binding = 2) readonly buffer Rate { float rate[]; };  // s, as the state
layout(std430, set = 0, binding = 3) coherent buffer Work { float work[]; };  // 5 M + M^2 floats
layout(std430, set = 0, binding = 4) writeonly buffer Status { SurfaceDyeStatus status; };
layout(push_constant) uniform Push { SurfaceDyeStepParams params; };

shared float partial[gl_WorkGroupSize.x];

// The five vectors of the iteration, M floats apart in `work`, then K (row-major).
const uint X = 0u, R = 1u, P = 2u, T = 3u, U = 4u, MATRIX = 5u;

uint at(uint vector, uint i) { return vector * params.m + i; }

void sync() {
    memoryBarrierBuffer();
    memoryBarrierShared();
    barrier();
}

// The workgroup's sum of every invocation's `value`.
float total(float value) {
    const uint lane = gl_LocalInvocationID.x;
    partial[lane] = value;
    barrier();
    for (uint half_ = gl_WorkGroupSize.x / 2u; half_ > 0u; half_ /= 2u) {
        if (lane < half_) partial[lane] += partial[lane + half_];
        barrier();
    }
    const float sum = partial[0];
    barrier();  // every invocation read it before the next total writes
    return sum;
}

// K_ij = pairs(i, j) above the diagonal, -pairs(j, i) below, into `work`.
void unpack() {
    const uint m = params.m, base = at(MATRIX, 0u);
    for (uint i = gl_LocalInvocationID.x; i < m; i += gl_WorkGroupSize.x) {
        work[base + i * m + i] = 0.0;
        const uint first = i * m - i * (i + 1u) / 2u - i - 1u;  // pairIndex(m, i, j) - j
        for (uint j = i + 1u; j < m; ++j) {
            const float k = pairs[first + j];
            work[base + i * m + j] = k;
            work[base + j * m + i] = -k;
        }
    }
    sync();
}

// (K x)_i for the vector x at `from`, as -(K^T x)_i = -sum_j K_ji x_j: column i of K^T is row i
// of K read across rows, consecutive in i.
float productRow(uint from, uint i) {
    const uint m = params.m, base = at(MATRIX, 0u);
    float sum = 0.0;
    for (uint j = 0u; j < m; ++j) sum -= work[base + j * m + i] * work[at(from, j)];
    return sum;
}

// work[to] = K work[from].
void product(uint from, uint to) {
    for (uint i = gl_LocalInvocationID.x; i < params.m; i += gl_WorkGroupSize.x)
        work[at(to, i)] = productRow(from, i);
    sync();
}

void main() {
    const uint m = params.m;
    const uint lane = gl_LocalInvocationID.x, lanes = gl_WorkGroupSize.x;
    const float h = params.h, a = 0.5 * h, a2 = a * a;
    if (lane == 0u) state[0] += h * rate[0];

    // b = f - a K f + h s (in T), then the normal equations' right-hand side c = b - a K b (in U),
    // and x = f.
    unpack();
    for (uint i = lane; i < m; i += lanes) work[at(X, i)] = state[1u + i];
    sync();
    product(X, U);
    for (uint i = lane; i < m; i += lanes)
        work[at(T, i)] = work[at(X, i)] - a * work[at(U, i)] + h * rate[1u + i];
    sync();
    product(T, U);
    float cc = 0.0;
    for (uint i = lane; i < m; i += lanes) {
        const float c = work[at(T, i)] - a * work[at(U, i)];
        work[at(R, i)] = c;  // r = c - B x, B x subtracted below
        cc += c * c;
    }
    cc = total(cc);
    sync();
    // r -= B x = x - a^2 K (K x); p = r.
    product(X, T);
    product(T, U);
    float rr = 0.0;
    for (uint i = lane; i < m; i += lanes) {
        const float r = work[at(R, i)] - work[at(X, i)] + a2 * work[at(U, i)];
        work[at(R, i)] = r;
        work[at(P, i)] = r;
        rr += r * r;
    }
    rr = total(rr);
    sync();

    const float goal = params.tolerance * params.tolerance * cc;
    uint iterations = 0u;
    while (rr > goal && iterations < params.maxIterations) {
        // q = B p (not stored: q_i = p_i - a^2 (K K p)_i), alpha = rr / p.q.
        product(P, T);
        product(T, U);
        float pq = 0.0;
        for (uint i = lane; i < m; i += lanes) {
            const float p = work[at(P, i)];
            pq += p * (p - a2 * work[at(U, i)]);
        }
        pq = total(pq);
        if (!(pq > 0.0)) break;  // exact solution reached (p = 0), or round-off
        const float alpha = rr / pq;
        float next = 0.0;
        for (uint i = lane; i < m; i += lanes) {
            const float p = work[at(P, i)];
            work[at(X, i)] += alpha * p;
            const float r = work[at(R, i)] - alpha * (p - a2 * work[at(U, i)]);
            work[at(R, i)] = r;
            next += r * r;
        }
        next = total(next);
        const float beta = next / rr;
        for (uint i = lane; i < m; i += lanes)
            work[at(P, i)] = work[at(R, i)] + beta * work[at(P, i)];
        sync();
        rr = next;
        ++iterations;
    }
    for (uint i = lane; i < m; i += lanes) state[1u + i] = work[at(X, i)];
    if (lane == 0u) {
        status.iterations = iterations;
        status.converged = rr <= goal ? 1u : 0u;
        status.residual = cc > 0.0 ? sqrt(rr / cc) : 0.0;
    }
}
