#version 450
// display_smoke_2d.comp: the stir window's picture of a 2D scene, each window pixel: the smoke sampled bilinearly between cell centres (the walls nearest-cell, so the
// domain's boundary shows as it is discretized), toned like the PNG previews, tinted where hot,
// glowing where fuel burns, with the text overlay on top; along a periodic axis the smoke and the arrows' velocity are
// sampled across the seam. Wrapper: engine/display/DisplayKernels.cpp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "DisplayParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Fields { vec2 fields[]; };  // (d, T) per cell
layout(std430, set = 0, binding = 1) readonly buffer Mask { uint maskWords[]; };  // 4 bytes a word
layout(std430, set = 0, binding = 2) readonly buffer Overlay { uint overlayWords[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Pixels { uint pixels[]; };
layout(std430, set = 0, binding = 4) readonly buffer Faces { float faces[]; };  // basis face velocity
layout(std430, set = 0, binding = 5) readonly buffer Flame { float flame[]; };  // read when flameScale > 0
layout(push_constant) uniform Push { DisplayParams params; };

#include "DisplayView.glsl"

#define MAC_DIM 2
// The face and its x-neighbour; on a periodic x the last face of a row pairs with the row's first
// (every face group's rows are basisX long then).
vec2 macFacePair(uint face) {
    const bool wrapX = (params.boundary & 1u) != 0u && face % params.basisX == params.basisX - 1u;
    const uint next = wrapX ? face + 1u - params.basisX : min(face + 1u, uint(faces.length()) - 1u);
    return vec2(faces[face], faces[next]);
}
#include "MacSampling.glsl"

float segmentDistance(vec2 p, vec2 a, vec2 b) {
    const vec2 ab = b - a;
    const float t = dot(ab, ab) > 0.0 ? clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0) : 0.0;
    return length(p - a - t * ab);
}

// The velocity arrow of the square of the arrow lattice holding window pixel (x, y): the MAC
// velocity at the square's centre, drawn through it (y up in the scene, down on screen).
vec3 withArrow(vec3 colour, uint x, uint y) {
    const vec2 local = vec2(ivec2(x, y) - ivec2(params.viewX, params.viewY)) + 0.5;
    const vec2 centre = (floor(local / params.arrowSpacing) + 0.5) * params.arrowSpacing;
    const vec2 view = vec2(params.viewWidth, params.viewHeight);
    if (any(greaterThan(centre, view))) return colour;
    const vec2 basis = vec2(params.basisX, params.basisY);
    const vec3 point = vec3(centre.x / view.x * basis.x, (1.0 - centre.y / view.y) * basis.y, 0.0);
    const ivec3 cells = ivec3(params.basisX, params.basisY, 1);
    const uint yOffset = (params.basisX + ((params.boundary & 1u) != 0u ? 0u : 1u)) * params.basisY;
    const vec2 u = vec2(sampleFaceComponent(0, point, cells, 0u, params.boundary),
                        sampleFaceComponent(1, point, cells, yOffset, params.boundary));
    vec2 d = vec2(u.x, -u.y) * params.arrowScale;
    const float limit = 0.9 * params.arrowSpacing;
    if (length(d) > limit) d *= limit / length(d);
    if (length(d) < 1.5) return colour;
    const vec2 tail = centre - 0.5 * d, tip = centre + 0.5 * d;
    const vec2 back = -normalize(d) * min(5.0, 0.4 * length(d)), side = vec2(-back.y, back.x) * 0.6;
    const float dist = min(segmentDistance(local, tail, tip),
                           min(segmentDistance(local, tip, tip + back + side),
                               segmentDistance(local, tip, tip + back - side)));
    return mix(colour, vec3(DISPLAY_ARROW_R, DISPLAY_ARROW_G, DISPLAY_ARROW_B), clamp(1.2 - dist, 0.0, 1.0));
}

bool isFluid(uint cell) { return ((maskWords[cell >> 2] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }

vec3 pixelColour(uint x, uint y) {
    vec3 colour = marginColour(x, y);
    vec2 p;
    if (sourcePoint(x, y, p)) {
        // Rows of the window run down, y of the grid up.
        p.y = float(params.sourceHeight) - p.y;
        const ivec2 n = ivec2(params.sourceWidth, params.sourceHeight);
        const ivec2 nearest = clamp(ivec2(floor(p)), ivec2(0), n - 1);
        if (!isFluid(uint(nearest.y * n.x + nearest.x))) {
            colour = vec3(DISPLAY_WALL_R, DISPLAY_WALL_G, DISPLAY_WALL_B);
        } else {
            vec2 s = clamp(p - 0.5, vec2(0.0), vec2(n - 1));
            ivec2 lo = min(ivec2(floor(s)), max(n - 2, ivec2(0)));
            ivec2 hi = min(lo + 1, n - 1);
            // Along a periodic axis the edge pixels blend with the other end's cells.
            [[unroll]] for (int a = 0; a < 2; ++a)
                if ((params.boundary & (1u << a)) != 0u) {
                    s[a] = mod(p[a] - 0.5, float(n[a]));
                    lo[a] = clamp(int(floor(s[a])), 0, n[a] - 1);
                    hi[a] = (lo[a] + 1) % n[a];
                }
            const vec2 f = s - vec2(lo);
            // Wall cells hold 0: the smoke fades into the wall rather than past it.
            const vec2 v = mix(mix(fields[lo.y * n.x + lo.x], fields[lo.y * n.x + hi.x], f.x),
                               mix(fields[hi.y * n.x + lo.x], fields[hi.y * n.x + hi.x], f.x), f.y);
            const float tone = min(1.0, (1.0 - exp(-DISPLAY_TONE * max(v.x, 0.0) / params.densityScale)) /
                                            (1.0 - exp(-DISPLAY_TONE)));
            const float heat = params.hotScale > 0.0 ? clamp(v.y / params.hotScale, 0.0, 1.0) : 0.0;
            const vec3 smoke = mix(vec3(DISPLAY_SMOKE_R, DISPLAY_SMOKE_G, DISPLAY_SMOKE_B),
                                   vec3(DISPLAY_HOT_R, DISPLAY_HOT_G, DISPLAY_HOT_B), 0.6 * heat);
            colour = mix(vec3(DISPLAY_BACKGROUND_R, DISPLAY_BACKGROUND_G, DISPLAY_BACKGROUND_B),
                         smoke, tone);
            if (params.flameScale > 0.0) {
                const float burning = mix(mix(flame[lo.y * n.x + lo.x], flame[lo.y * n.x + hi.x], f.x),
                                          mix(flame[hi.y * n.x + lo.x], flame[hi.y * n.x + hi.x], f.x), f.y);
                colour = mix(colour, vec3(DISPLAY_FLAME_R, DISPLAY_FLAME_G, DISPLAY_FLAME_B),
                             clamp(burning / params.flameScale, 0.0, 1.0));
            }
        }
        if (params.arrows != 0u) colour = withArrow(colour, x, y);
        colour = withPaddle(colour, p);
    }
    return colour;
}

#include "Display.glsl"
