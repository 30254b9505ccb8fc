#version 450
// Second pass of the tensor-free advection (engine/device/TensorFreeAdvection): per velocity DOF
// d, the transposed quadrature applied to the element products of advection_samples.comp,
//
//     q[d] = sum over the entries of d: coefficient * samples[slot]
//
// (C(a, b): the velocity components' transposes; advect: the curl's), the coefficients divided by
// the projection weight of d, so that project_force.comp's sum_d Psi_k[d] w_d q[d] is Psi^T g.
// A gather, one invocation per DOF: no atomics, deterministic.
#extension GL_GOOGLE_include_directive : require
#include "AdvectionParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer RowStart { uint rowStart[]; };
layout(std430, set = 0, binding = 1) readonly buffer Entries { uvec2 entries[]; };  // slot, coefficient bits
layout(std430, set = 0, binding = 2) readonly buffer Samples { float samples[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Result { float q[]; };
layout(push_constant) uniform Push { AdvectionGatherParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint d = gl_GlobalInvocationID.x; d < params.dofCount; d += stride) {
        float sum = 0.0;
        for (uint t = rowStart[d]; t < rowStart[d + 1u]; ++t)
            sum += uintBitsToFloat(entries[t].y) * samples[entries[t].x];
        q[d] = sum;
    }
}
