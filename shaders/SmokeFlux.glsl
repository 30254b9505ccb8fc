/* SmokeFlux.glsl: the conservative smoke transport on the device, float32, the body of the
   smoke_flux_<stage>_<dim>d kernels, which define SMOKE_FLUX_STAGE and SMOKE_DIM (CPU reference
   and the rules: engine/reference/ConservativeTransport.h; the host side:
   engine/device/ConservativeTransport.h). A step is

     velocity:  u on every smoke face: the basis velocity MAC-sampled at its centre where the face
                moves smoke (both cells fluid, or a side the air crosses beside a fluid cell), else 0
     courant:   the largest sum over axes of max |u| on a cell's two faces times dt / h, an atomic
                max of its float bits (non-negative floats order as their bits)
     ... the host reads it and takes fluxSubsteps() of
     step:      per fluid cell, from `fieldsIn` to `fieldsOut`: the cell's value minus the substep
                times the divergence of its faces' fluxes u * phi_face, phi_face the upwind value
                plus half its minmod-limited slope (MUSCL), or beyond an inflow side the ghost

   Each cell computes the fluxes of its own faces, so a face's flux is computed twice, by the same
   expression from the same values: what one cell loses the other gains, and a substep is one
   dispatch (the fields ping-pong between the state's two buffers). */
#ifndef MODEFLOW_SHADERS_SMOKE_FLUX_GLSL
#define MODEFLOW_SHADERS_SMOKE_FLUX_GLSL

#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "SmokeAdvectParams.h"
#include "SmokeFluxParams.h"
#include "OutsideAir.glsl"

#define SMOKE_FLUX_VELOCITY 0
#define SMOKE_FLUX_COURANT 1
#define SMOKE_FLUX_STEP 2

layout(local_size_x = 128, local_size_x_id = 0) in;
layout(push_constant) uniform Push { SmokeFluxParams params; };

#if SMOKE_FLUX_STAGE == SMOKE_FLUX_VELOCITY
layout(set = 0, binding = 0) uniform usamplerBuffer facePairs;  // smoke_face_pairs.comp's
layout(set = 0, binding = 1) uniform usamplerBuffer mask;       // 4 cells a (R32UI) texel
layout(std430, set = 0, binding = 2) writeonly buffer FaceVelocity { float faceVelocity[]; };
vec2 macFacePair(uint face) { return uintBitsToFloat(texelFetch(facePairs, int(face)).xy); }
#define MAC_DIM SMOKE_DIM
#include "MacSampling.glsl"
#elif SMOKE_FLUX_STAGE == SMOKE_FLUX_COURANT
layout(set = 0, binding = 0) uniform usamplerBuffer faceVelocity;  // one float a (R32UI) texel
layout(std430, set = 0, binding = 1) buffer Worst { uint worst; };
#else
layout(set = 0, binding = 0) uniform usamplerBuffer fluidCells;    // one entry a texel
layout(set = 0, binding = 1) uniform usamplerBuffer mask;          // 4 cells a (R32UI) texel
layout(set = 0, binding = 2) uniform usamplerBuffer faceVelocity;  // one float a (R32UI) texel
layout(set = 0, binding = 3) uniform usamplerBuffer fieldsIn;      // one cell a word texel
layout(set = 0, binding = 4) uniform usamplerBuffer ghosts;        // OutsideAir's, one a texel
layout(std430, set = 0, binding = 5) writeonly buffer FieldsOut { uint64_t fieldsOut[]; };
layout(std430, set = 0, binding = 6) writeonly buffer SecondOut { float secondOut[]; };
#endif

ivec3 smokeCells() { return ivec3(params.cellsX, params.cellsY, params.cellsZ); }
bool periodicAxis(int a) { return (params.boundary & (1u << uint(a))) != 0u; }
int cellIndex(ivec3 p) { return (p.z * int(params.cellsY) + p.y) * int(params.cellsX) + p.x; }

// The smoke face of `axis` at `p` (MacGrid::faceIndex of the smoke grid).
int faceIndex(int axis, ivec3 p) {
    ivec3 extent = smokeCells();
    extent[axis] += periodicAxis(axis) ? 0 : 1;
    const int offset = axis == 0 ? 0 : int(axis == 1 ? params.smokeFaceOffsetY : params.smokeFaceOffsetZ);
    return offset + (p.z * extent.y + p.y) * extent.x + p.x;
}

#if SMOKE_FLUX_STAGE != SMOKE_FLUX_COURANT
bool fluidAt(ivec3 p) {
    const int c = cellIndex(p);
    return ((texelFetch(mask, c >> 2).x >> (uint(c & 3) * 8u)) & 0xffu) != 0u;
}

// The cell `by` cells from p along `axis` (wrapped along a periodic one), when it lies in the box
// and is fluid.
bool neighbour(ivec3 p, int axis, int by, out ivec3 cell) {
    cell = p;
    cell[axis] += by;
    const int n = smokeCells()[axis];
    if (!periodicAxis(axis) && (cell[axis] < 0 || cell[axis] >= n)) return false;
    cell[axis] = (cell[axis] % n + n) % n;
    return fluidAt(cell);
}
#endif

#if SMOKE_FLUX_STAGE == SMOKE_FLUX_VELOCITY
// Whether the face of `axis` at `p` moves smoke (ConservativeTransport::moves).
bool moves(int axis, ivec3 p) {
    const int n = smokeCells()[axis];
    const bool hasLower = periodicAxis(axis) || p[axis] > 0;
    const bool hasUpper = periodicAxis(axis) || p[axis] < n;
    ivec3 lower = p;
    lower[axis] = ((p[axis] - 1) % n + n) % n;
    if (hasLower && hasUpper) return fluidAt(lower) && fluidAt(p);
    const int side = 2 * axis + (hasLower ? 1 : 0);
    return (params.crossable & (1u << uint(side))) != 0u && fluidAt(hasLower ? lower : p);
}

void main() {
    const uint f = params.first + gl_GlobalInvocationID.x;
    if (f >= params.count) return;
    int axis = 0;
    int local = int(f);
    if (SMOKE_DIM == 3 && f >= params.smokeFaceOffsetZ) {
        axis = 2;
        local -= int(params.smokeFaceOffsetZ);
    } else if (f >= params.smokeFaceOffsetY) {
        axis = 1;
        local -= int(params.smokeFaceOffsetY);
    }
    ivec3 extent = smokeCells();
    extent[axis] += periodicAxis(axis) ? 0 : 1;
    const ivec3 p = ivec3(local % extent.x, (local / extent.x) % extent.y, local / (extent.x * extent.y));
    float u = 0.0;
    if (moves(axis, p)) {
        vec3 g = vec3(0.5);
        [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a)
            g[a] = (float(p[a]) + (a == axis ? 0.0 : 0.5)) / float(params.scale);
        const uint offset = axis == 0 ? 0u : (axis == 1 ? params.faceOffsetY : params.faceOffsetZ);
        u = sampleFaceComponent(axis, g, ivec3(params.basisX, params.basisY, params.basisZ), offset,
                                params.boundary);
        if (isnan(u) || isinf(u)) u = 0.0;  // a diverged run moves nothing, as the other schemes
    }
    faceVelocity[f] = u;
}

#elif SMOKE_FLUX_STAGE == SMOKE_FLUX_COURANT
float faceU(int face) { return uintBitsToFloat(texelFetch(faceVelocity, face).x); }

void main() {
    const uint c = params.first + gl_GlobalInvocationID.x;
    if (c >= params.count) return;
    const ivec3 cells = smokeCells();
    const ivec3 p = ivec3(int(c) % cells.x, (int(c) / cells.x) % cells.y, int(c) / (cells.x * cells.y));
    const vec3 spacing = vec3(params.spacingX, params.spacingY, params.spacingZ);
    float courant = 0.0;
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a) {
        ivec3 above = p;
        above[a] = (p[a] + 1) % (periodicAxis(a) ? cells[a] : cells[a] + 1);
        courant += max(abs(faceU(faceIndex(a, p))), abs(faceU(faceIndex(a, above)))) * params.dt / spacing[a];
    }
    atomicMax(worst, floatBitsToUint(courant));
}

#else
vec2 fieldAt(ivec3 p) { return uintBitsToFloat(texelFetch(fieldsIn, cellIndex(p)).xy); }

vec2 minmod(vec2 a, vec2 b) {
    vec2 m;
    [[unroll]] for (int k = 0; k < 2; ++k)
        m[k] = a[k] * b[k] <= 0.0 ? 0.0 : (abs(a[k]) < abs(b[k]) ? a[k] : b[k]);
    return m;
}

// The flux u * phi_face of both fields through the face of `axis` at `q` (ConservativeTransport).
vec2 fluxAt(int axis, ivec3 q) {
    const float u = uintBitsToFloat(texelFetch(faceVelocity, faceIndex(axis, q)).x);
    if (u == 0.0) return vec2(0.0);
    // The cells below (-1) and above (0) the face, and the upwind one of them.
    const int upwind = u > 0.0 ? -1 : 0, downwind = u > 0.0 ? 0 : -1;
    ivec3 up, down, beyond;
    const bool hasUp = neighbour(q, axis, upwind, up);
    const bool hasDown = neighbour(q, axis, downwind, down);
    vec2 value;
    if (!hasUp) {  // the air comes in across a side
        const int side = 2 * axis + (upwind == 0 ? 1 : 0);
        const uint inflow = 1u << ((side & 1) == 0 ? SMOKE_INFLOW_LOW + uint(axis) : SMOKE_INFLOW_HIGH + uint(axis));
        value = (params.boundary & inflow) != 0u
                    ? ghostPairOf(texelFetch(ghosts, ghostIndex(side, q, smokeCells())), params.ghostPair)
                    : fieldAt(down);
    } else {
        const vec2 here = fieldAt(up);
        const vec2 slope = hasDown && neighbour(q, axis, u > 0.0 ? -2 : 1, beyond)
                               ? minmod(here - fieldAt(beyond), fieldAt(down) - here)
                               : vec2(0.0);
        value = here + 0.5 * slope;
    }
    return u * value;
}

void main() {
    const uint entry = params.first + gl_GlobalInvocationID.x;
    if (entry >= params.count) return;
    const uvec4 listed = texelFetch(fluidCells, int(entry));
    const ivec3 cell = ivec3(listed.x & 0xffffu, listed.x >> 16, listed.y);
    const ivec3 cells = smokeCells();
    const vec3 spacing = vec3(params.spacingX, params.spacingY, params.spacingZ);
    vec2 change = vec2(0.0);
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a) {
        ivec3 above = cell;
        above[a] = (cell[a] + 1) % (periodicAxis(a) ? cells[a] : cells[a] + 1);
        change += (fluxAt(a, above) - fluxAt(a, cell)) / spacing[a];
    }
    vec2 value = fieldAt(cell) - params.substep * change;
    const int id = cellIndex(cell);
    if (params.last != 0u) {  // the emitters, after the transport, as on the CPU
        value += uintBitsToFloat(listed.zw) * params.dt;
        secondOut[id] = value.y;
    }
    fieldsOut[id] = pack64(floatBitsToUint(value));
}
#endif

#endif
