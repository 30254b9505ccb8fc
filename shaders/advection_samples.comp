#version 450
// First pass of the tensor-free advection (engine/device/TensorFreeAdvection; CPU reference:
// engine/dynamics/TensorFreeCoefficients), one invocation per vorticity element e: the weighted
// vorticity and the two velocity components at e from face fields (the reconstructions of the
// two contracted vectors), with the quadrature of the coefficient assembly
//
//     omega(a) = sum_s curl_s fa[face_s],  p(b) = sum_s first_s fb[..],  q(b) = sum_s second_s fb[..]
//
// (coefficients scaled by the face areas, since a face field holds flux / area), and the products
// the second pass gathers: C(a, b) needs (omega(a) q(b), -omega(a) p(b)), advect(u, x) needs
// p(u) q(x) - q(u) p(x). Unused slots have coefficient 0.
#extension GL_GOOGLE_include_directive : require
#include "AdvectionParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
layout(constant_id = 1) const uint OP = ADVECTION_APPLY;

layout(set = 0, binding = 0) uniform usamplerBuffer elements;
layout(std430, set = 0, binding = 1) readonly buffer FieldA { float fa[]; };
layout(std430, set = 0, binding = 2) readonly buffer FieldB { float fb[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Samples { vec2 samples[]; };
layout(push_constant) uniform Push { AdvectionSampleParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint e = gl_GlobalInvocationID.x; e < params.elementCount; e += stride) {
        const uint at = ADVECTION_ELEMENT_TEXELS * e;
        const uvec4 curlFaces = texelFetch(elements, int(at));
        const uvec4 velocityFaces = texelFetch(elements, int(at + 1u));
        const vec4 curl = uintBitsToFloat(texelFetch(elements, int(at + 2u)));
        const vec4 velocity = uintBitsToFloat(texelFetch(elements, int(at + 3u)));
        const float pb = velocity.x * fb[velocityFaces.x] + velocity.y * fb[velocityFaces.y];
        const float qb = velocity.z * fb[velocityFaces.z] + velocity.w * fb[velocityFaces.w];
        if (OP == ADVECTION_APPLY) {
            const float omega = curl.x * fa[curlFaces.x] + curl.y * fa[curlFaces.y] +
                                curl.z * fa[curlFaces.z] + curl.w * fa[curlFaces.w];
            samples[e] = vec2(omega * qb, -omega * pb);
        } else {
            const float pa = velocity.x * fa[velocityFaces.x] + velocity.y * fa[velocityFaces.y];
            const float qa = velocity.z * fa[velocityFaces.z] + velocity.w * fa[velocityFaces.w];
            samples[e] = vec2(pa * qb - qa * pb, 0.0);
        }
    }
}
