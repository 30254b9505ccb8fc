#version 450
// Force density g on the velocity DOFs (DESIGN sections 3-4; CPU reference and definitions:
// engine/field/ForceField.h): buoyancy times the mean temperature over the dual cell of each
// up-facing face, plus Gaussian stirring splats (force . n) exp(-|x - centre|^2 / radius^2) at
// the face centres. One invocation per DOF; the summation order matches the CPU reference.
#extension GL_GOOGLE_include_directive : require
#include "ForceFieldParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 1) readonly buffer Temperature { float temperature[]; };
layout(std430, set = 0, binding = 2) readonly buffer Mask { uint maskWords[]; };  // 4 bytes a word
layout(std430, set = 0, binding = 3) readonly buffer Splats { ForceSplatRecord splats[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Density { float g[]; };
layout(push_constant) uniform Push { ForceFieldParams params; };

#include "FaceLocation.glsl"

bool isFluid(uint cell) { return ((maskWords[cell >> 2] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }

// Mean temperature over the dual cell of the up-facing face at `pos`: s smoke cells across per
// tangential axis, [p s - s/2, p s + s/2] along up (odd s: the end cells count half).
float dualCellTemperature(uvec3 pos, uint up) {
    const int s = int(params.scale);
    const int reach = (s + 1) / 2;
    ivec3 begin = ivec3(0), end = ivec3(1);
    for (uint a = 0u; a < params.dim; ++a) {
        begin[a] = a == up ? int(pos[a]) * s - reach : int(pos[a]) * s;
        end[a] = a == up ? int(pos[a]) * s + reach : int(pos[a] + 1u) * s;
    }
    const float endWeight = (s & 1) != 0 ? 0.5 : 1.0;
    const ivec3 smokeCells = ivec3(params.cells[0], params.cells[1], params.cells[2]) *
                             ivec3(s, s, params.dim == 3u ? s : 1);
    float sum = 0.0, weight = 0.0;
    for (int z = max(begin.z, 0); z < min(end.z, smokeCells.z); ++z)
        for (int y = max(begin.y, 0); y < min(end.y, smokeCells.y); ++y)
            for (int x = max(begin.x, 0); x < min(end.x, smokeCells.x); ++x) {
                const uint cell = uint((z * smokeCells.y + y) * smokeCells.x + x);
                if (params.useMask != 0u && !isFluid(cell)) continue;
                const int along = up == 1u ? y : z;
                const float w = along == begin[up] || along == end[up] - 1 ? endWeight : 1.0;
                sum += w * temperature[cell];
                weight += w;
            }
    return weight > 0.0 ? sum / weight : 0.0;
}

float splatForce(uvec3 pos, uint axis) {
    float value = 0.0;
    for (uint k = 0u; k < params.splatCount; ++k) {
        float r2 = 0.0;
        for (uint a = 0u; a < params.dim; ++a) {
            const float x = params.origin[a] + (float(pos[a]) + (a == axis ? 0.0 : 0.5)) * params.spacing[a];
            r2 += (x - splats[k].centre[a]) * (x - splats[k].centre[a]);
        }
        value += splats[k].force[axis] * exp(-r2 / (splats[k].radius * splats[k].radius));
    }
    return value;
}

void main() {
    const uint invocations = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    const uvec3 cells = uvec3(params.cells[0], params.cells[1], params.cells[2]);
    const uint up = params.dim - 1u;
    for (uint d = gl_GlobalInvocationID.x; d < params.dofCount; d += invocations) {
        const uint face = faces[d];
        const uint axis = faceAxis(face, params.faceStart1, params.faceStart2);
        const uint start = axis == 0u ? 0u : (axis == 1u ? params.faceStart1 : params.faceStart2);
        const uvec3 pos = facePosition(face - start, axis, cells);
        float value = splatForce(pos, axis);
        if (axis == up && params.buoyancy != 0.0) value += params.buoyancy * dualCellTemperature(pos, up);
        g[d] = value;
    }
}
