#version 450
// Preview of 3D smoke: a ray-marched volume rendering, the device twin of the CPU reference
// engine/preview/VolumeReference.cpp (same steps in the same order, float32). Two stages:
//
// - light (one invocation per (x, y) column): extinction sigma = densityScale * density of each
//   fluid cell (-1 marks a wall cell) and the optical depth from the cell centre up to the top
//   of the box. The light comes straight from +z, so this column sum is every sample's shadow
//   ray (Beer-Lambert) done once per cell instead of once per sample.
// - image (one invocation per pixel): a ray from the camera through the box, sampled every
//   stepT; each sample scatters (light * exp(-depth) + ambient) times the part of the
//   remaining light it absorbs (single scattering), and where the trilinear fluid mask w is
//   between 0 and 1 (within a cell of the domain's wall) a faint glass 4 w (1 - w) glows, more
//   where the ray grazes the wall, so the domain and its obstacles show; in the flame variant
//   (specialization constant withFlame) the trilinear flame glows flame-coloured, dimmed by the
//   smoke in front. Box edges are drawn faintly behind the volume and in front of it.
// Fields are sampled trilinearly between cell centres, clamped at the box's walls and wrapping
// across its periodic axes, like MacSampling.glsl.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "AxisStencil.glsl"
#include "RenderVolumeParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
// Compiled out without a fire: 8 more loads a sample.
layout(constant_id = 1) const bool withFlame = false;

layout(std430, set = 0, binding = 0) readonly buffer Density { float density[]; };
layout(std430, set = 0, binding = 1) readonly buffer Mask { uint maskWords[]; };  // 4 bytes a word
layout(std430, set = 0, binding = 2) buffer Extinction { float extinction[]; };
layout(std430, set = 0, binding = 3) buffer Depth { float depth[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Pixels { uint pixels[]; };  // RGBA8, R low
layout(std430, set = 0, binding = 5) readonly buffer Flame { float flame[]; };  // one float a cell
layout(push_constant) uniform Push { RenderVolumeParams params; };

bool isFluid(uint cell) { return ((maskWords[cell >> 2] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }

void lightColumn(uint column) {
    const uint layer = params.cellsX * params.cellsY;
    float above = 0.0;
    for (int z = int(params.cellsZ) - 1; z >= 0; --z) {
        const uint cell = uint(z) * layer + column;
        const bool fluid = isFluid(cell);
        const float d = density[cell * params.densityStride];
        const float sigma = fluid && d > 0.0 ? d * params.densityScale : 0.0;
        extinction[cell] = fluid ? sigma : -1.0;
        depth[cell] = above + 0.5 * params.hz * sigma;
        above += params.hz * sigma;
    }
}

// The 8 cells around a point and their trilinear weights.
struct Stencil {
    uint cell[8];
    float weight[8];
};

Stencil stencilAt(vec3 p) {
    const ivec3 n = ivec3(params.cellsX, params.cellsY, params.cellsZ);
    ivec3 lo, hi;
    vec3 f;
    for (int a = 0; a < 3; ++a) {
        const AxisStencil s = axisStencil(p[a], 0.5, n[a], isPeriodic(params.periodic, a));
        lo[a] = s.lo;
        hi[a] = s.hi;
        f[a] = s.f;
    }
    Stencil st;
    [[unroll]] for (int k = 0; k < 8; ++k) {
        const ivec3 c = ivec3((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y,
                              (k & 4) != 0 ? hi.z : lo.z);
        st.cell[k] = uint((c.z * n.y + c.y) * n.x + c.x);
        st.weight[k] = ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k & 2) != 0 ? f.y : 1.0 - f.y) *
                       ((k & 4) != 0 ? f.z : 1.0 - f.z);
    }
    return st;
}

// (extinction, fluid fraction) at the stencil's point.
vec2 sampleExtinction(Stencil st) {
    vec2 sum = vec2(0.0);
    [[unroll]] for (int k = 0; k < 8; ++k) {
        const float e = extinction[st.cell[k]];
        sum += st.weight[k] * vec2(max(e, 0.0), e >= 0.0 ? 1.0 : 0.0);
    }
    return sum;
}

float sampleFlame(Stencil st) {
    float sum = 0.0;
    [[unroll]] for (int k = 0; k < 8; ++k) sum += st.weight[k] * flame[st.cell[k]];
    return sum;
}

float sampleDepth(Stencil st) {
    float sum = 0.0;
    [[unroll]] for (int k = 0; k < 8; ++k) sum += st.weight[k] * depth[st.cell[k]];
    return sum;
}

// How much of a box edge covers the pixel whose ray meets the box surface at p (cell units)
// at distance t: p lies on one face; the second nearest face is the distance to an edge.
float edgeCoverage(vec3 p, float t, vec3 cellsPerT) {
    const vec3 n = vec3(params.cellsX, params.cellsY, params.cellsZ);
    const vec3 d = max(min(p, n - p), vec3(0.0)) / cellsPerT;
    const float second = max(min(d.x, d.y), min(max(d.x, d.y), d.z));
    return clamp(1.25 - second / (t * params.pixelAngle), 0.0, 1.0);
}

float encode(float linear) { return linear > 0.0 ? pow(linear, 1.0 / 2.2) : 0.0; }

void renderPixel(uint pixel) {
    const uint px = pixel % params.width;
    const uint py = pixel / params.width;
    const vec3 world = normalize(vec3(params.baseX, params.baseY, params.baseZ) +
                                 (float(px) + 0.5) * vec3(params.dxX, params.dxY, params.dxZ) +
                                 (float(py) + 0.5) * vec3(params.dyX, params.dyY, params.dyZ));
    const vec3 cellsPerT = vec3(params.cellsPerTX, params.cellsPerTY, params.cellsPerTZ);
    const vec3 dir = world * cellsPerT;
    const vec3 eye = vec3(params.eyeX, params.eyeY, params.eyeZ);
    const vec3 n = vec3(params.cellsX, params.cellsY, params.cellsZ);

    // Slab test against the box [0, n]; tiny direction components stand in for 0 (no inf * 0).
    float tNear = 0.0, tFar = 1e30;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0 / (abs(dir[a]) < 1e-20 ? 1e-20 : dir[a]);
        const float t0 = (0.0 - eye[a]) * inv;
        const float t1 = (n[a] - eye[a]) * inv;
        tNear = max(tNear, min(t0, t1));
        tFar = min(tFar, max(t0, t1));
    }
    const vec3 lightColour =
        vec3(RENDER_VOLUME_LIGHT_R, RENDER_VOLUME_LIGHT_G, RENDER_VOLUME_LIGHT_B);
    const vec3 ambient =
        vec3(RENDER_VOLUME_AMBIENT_R, RENDER_VOLUME_AMBIENT_G, RENDER_VOLUME_AMBIENT_B);
    const vec3 glass = vec3(RENDER_VOLUME_GLASS_R, RENDER_VOLUME_GLASS_G, RENDER_VOLUME_GLASS_B);
    const vec3 flameColour =
        vec3(RENDER_VOLUME_FLAME_R, RENDER_VOLUME_FLAME_G, RENDER_VOLUME_FLAME_B);
    const vec3 outline =
        vec3(RENDER_VOLUME_OUTLINE_R, RENDER_VOLUME_OUTLINE_G, RENDER_VOLUME_OUTLINE_B);
    vec3 background =
        vec3(RENDER_VOLUME_BACKGROUND_R, RENDER_VOLUME_BACKGROUND_G, RENDER_VOLUME_BACKGROUND_B);
    vec3 light = vec3(0.0);
    float transmittance = 1.0;
    const bool hit = tNear < tFar;
    if (hit) {
        const float back = edgeCoverage(eye + tFar * dir, tFar, cellsPerT);
        background = mix(background, outline, RENDER_VOLUME_BACK_EDGE * back);
        const int steps = max(1, int(ceil((tFar - tNear) / params.stepT)));
        const float dt = (tFar - tNear) / float(steps);
        const float glassPerStep = dt / params.glassT;
        for (int i = 0; i < steps; ++i) {
            const Stencil st = stencilAt(eye + (tNear + (float(i) + 0.5) * dt) * dir);
            const vec2 e = sampleExtinction(st);
            light += transmittance * (glassPerStep * 4.0 * e.y * (1.0 - e.y)) * glass;
            if (withFlame)
                light += transmittance * (params.flameScale * sampleFlame(st) * dt) * flameColour;
            if (e.x > 0.0) {
                const float absorbed = 1.0 - exp(-e.x * dt);
                light += transmittance * absorbed * (lightColour * exp(-sampleDepth(st)) + ambient);
                transmittance *= 1.0 - absorbed;
                if (transmittance < RENDER_VOLUME_MIN_TRANSMITTANCE) break;
            }
        }
    }
    const vec3 exposed = vec3(1.0) - exp(-RENDER_VOLUME_EXPOSURE * light);
    vec3 colour = vec3(encode(exposed.r), encode(exposed.g), encode(exposed.b)) +
                  transmittance * background;
    if (hit) {
        const float front = edgeCoverage(eye + tNear * dir, tNear, cellsPerT);
        colour = mix(colour, outline, RENDER_VOLUME_FRONT_EDGE * front);
    }
    const uvec3 bytes = uvec3(clamp(colour, 0.0, 1.0) * 255.0 + 0.5);
    pixels[pixel] = bytes.r | (bytes.g << 8) | (bytes.b << 16) | (255u << 24);
}

void main() {
    const uint invocations = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint item = gl_GlobalInvocationID.x; item < params.itemCount; item += invocations) {
        if (params.stage == RENDER_VOLUME_STAGE_LIGHT)
            lightColumn(item);
        else
            renderPixel(item);
    }
}
