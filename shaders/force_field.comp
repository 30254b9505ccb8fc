#version 450
// Force density g on the velocity DOFs (engine/README.md "Reduced dynamics"; CPU reference and definitions:
// engine/reference/ForceField.h): Gaussian stirring splats (force . n) exp(-|x - centre|^2 / radius^2)
// at the face centres, plus buoyancy times the mean temperature over the dual cell of each
// up-facing face. Two stages, one pipeline each (engine/device/ForceField; without splats the
// host fills g with zeros instead of the first):
//   STAGE_SPLATS  g = splats on every DOF,
//   STAGE_BUOYANCY g += buoyancy * dual-cell temperature on the up DOFs only, from a host-made
//                 list of (DOF, face position) texels; the CPU reference sums in the same order;
//                 without splats g = (ACCUMULATE 0: no load of g, a scalar access per lane on
//                 lavapipe, measurably faster, and the fill of g left out where only the up
//                 DOFs are read: precompute/README.md "Closed-form bases").
// Why, measured on lavapipe (tools/bench/bench_runtime `forces`, engine/README.md "Speed"): one pass over
// every DOF with the buoyancy behind `if (axis == up)` and the dual cell's loop bounds per lane ran
// the dual-cell code for every DOF (an `if` on lavapipe masks lanes, its body runs), decoded the
// face position by integer division and looped with lane-varying bounds. The stages, the up list
// and the scale and dimension as specialization constants (the dual cell's loops unroll, cells
// outside the grid weigh 0) remove all three.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "ForceFieldParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
layout(constant_id = 1) const uint STAGE = 0u;     // FORCE_STAGE_* (ForceFieldParams.h)
layout(constant_id = 2) const uint DIM = 3u;       // 2 or 3; up is axis DIM - 1
layout(constant_id = 3) const uint SCALE = 1u;     // smoke cells per basis cell and axis
layout(constant_id = 4) const uint USE_MASK = 0u;  // 1: average over fluid smoke cells only
layout(constant_id = 5) const uint ACCUMULATE = 1u;  // buoyancy: 1 adds to g, 0 assigns it

layout(std430, set = 0, binding = 0) readonly buffer Faces { uint faces[]; };
// Per up DOF: the DOF, and its face's lower-corner position x, y, z.
layout(set = 0, binding = 1) uniform usamplerBuffer upDofs;
// The smoke temperature, one cell a texel (R32UI): a texel fetch is one gather for all lanes where
// a storage load is a scalar access per lane on lavapipe (TexelAccess.glsl), and one component
// gathers a quarter of what an RGBA32UI texel and a select of its component do.
layout(set = 0, binding = 2) uniform usamplerBuffer temperatureTexels;
layout(std430, set = 0, binding = 3) readonly buffer Mask { uint maskWords[]; };  // 4 bytes a word
layout(std430, set = 0, binding = 4) readonly buffer Splats { ForceSplatRecord splats[]; };
layout(std430, set = 0, binding = 5) buffer Density { float g[]; };
layout(push_constant) uniform Push { ForceFieldParams params; };

#include "FaceLocation.glsl"

bool isFluid(uint cell) { return ((maskWords[cell >> 2] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }

const uint UP = DIM - 1u;
const int REACH = int(SCALE + 1u) / 2;  // smoke cells of the dual cell on each side of the face
const int ALONG = 2 * REACH;            // smoke cells of the dual cell along up
const float END_WEIGHT = (SCALE & 1u) != 0u ? 0.5 : 1.0;  // odd scale: the end cells count half

// Mean temperature over the dual cell of the up-facing face at `pos`: SCALE smoke cells across
// per tangential axis, [p s - REACH, p s + REACH) along up, cells outside the grid (and, with the
// mask, solid ones) left out; along a periodic up axis those are the other end's cells.
float dualCellTemperature(uvec3 pos) {
    const ivec3 smokeCells = ivec3(params.cells[0], params.cells[1], params.cells[2]) *
                             ivec3(SCALE, SCALE, DIM == 3u ? SCALE : 1u);
    ivec3 begin = ivec3(pos) * int(SCALE);
    begin[UP] -= REACH;
    const int countY = UP == 1u ? ALONG : int(SCALE);
    const int countZ = DIM == 3u ? ALONG : 1;
    float sum = 0.0, weight = 0.0;
    [[unroll]] for (int k = 0; k < countZ; ++k)
        [[unroll]] for (int j = 0; j < countY; ++j)
            [[unroll]] for (int i = 0; i < int(SCALE); ++i) {
                ivec3 c = begin + ivec3(i, j, k);
                const int step = UP == 1u ? j : k;  // position along up within the dual cell
                float w = step == 0 || step == ALONG - 1 ? END_WEIGHT : 1.0;
                if ((params.periodic & (1u << UP)) != 0u) {
                    // REACH < one period; selects, not %: lavapipe divides lane by lane, and
                    // runs both sides of this `if` (with the mask also left out where no smoke
                    // cell is solid, a much cheaper buoyancy pass: precompute/README.md).
                    const int n = smokeCells[UP];
                    c[UP] += c[UP] < 0 ? n : (c[UP] >= n ? -n : 0);
                } else {
                    if (c[UP] < 0 || c[UP] >= smokeCells[UP]) w = 0.0;
                    c[UP] = clamp(c[UP], 0, smokeCells[UP] - 1);  // read in bounds, weigh 0
                }
                const uint cell = uint((c.z * smokeCells.y + c.y) * smokeCells.x + c.x);
                if (USE_MASK != 0u && !isFluid(cell)) w = 0.0;
                sum += w * uintBitsToFloat(texelFetch(temperatureTexels, int(cell)).x);
                weight += w;
            }
    return weight > 0.0 ? sum / weight : 0.0;
}

float splatForce(uint face) {
    const uint axis = faceAxis(face, params.faceStart1, params.faceStart2);
    const uint start = axis == 0u ? 0u : (axis == 1u ? params.faceStart1 : params.faceStart2);
    const uvec3 cells = uvec3(params.cells[0], params.cells[1], params.cells[2]);
    const uvec3 pos = facePosition(face - start, axis, cells, params.periodic);
    const vec3 spacing = vec3(params.spacing[0], params.spacing[1], params.spacing[2]);
    vec3 x = vec3(0.0);
    [[unroll]] for (uint a = 0u; a < DIM; ++a)
        x[a] = params.origin[a] + (float(pos[a]) + (a == axis ? 0.0 : 0.5)) * params.spacing[a];
    float value = 0.0;
    for (uint k = 0u; k < params.splatCount; ++k) {
        vec3 d = x - vec3(splats[k].centre[0], splats[k].centre[1], splats[k].centre[2]);
        if (DIM == 2u) d.z = 0.0;
        d = minimumImage(d, vec3(cells) * spacing, params.periodic);
        value += splats[k].force[axis] * exp(-dot(d, d) / (splats[k].radius * splats[k].radius));
    }
    return value;
}

void main() {
    const uint invocations = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    if (STAGE == FORCE_STAGE_BUOYANCY) {
        for (uint i = gl_GlobalInvocationID.x; i < params.upCount; i += invocations) {
            const uvec4 entry = texelFetch(upDofs, int(i));
            const float force = params.buoyancy * dualCellTemperature(entry.yzw);
            if (ACCUMULATE != 0u) g[entry.x] += force;
            else g[entry.x] = force;
        }
    } else {
        for (uint d = gl_GlobalInvocationID.x; d < params.dofCount; d += invocations)
            g[d] = splatForce(faces[d]);
    }
}
