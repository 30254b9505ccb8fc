#version 450
// v -= dv over the N modes: the moving-obstacle correction (obstacle_mismatch.comp) applied to
// the modal state in place.
#extension GL_GOOGLE_include_directive : require
#include "ObstacleParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) buffer State { float v[]; };
layout(std430, set = 0, binding = 1) readonly buffer Correction { float dv[]; };
layout(push_constant) uniform Push { ModalCorrectParams params; };

void main() {
    const uint k = gl_GlobalInvocationID.x;
    if (k < params.n) v[k] -= dv[k];
}
