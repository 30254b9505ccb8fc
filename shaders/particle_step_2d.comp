#version 450
// One step of the particles on a 2D grid: ParticleStep.glsl with its dimension fixed at compile
// time (MacSampling.glsl's stencils unroll over it).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#define MAC_DIM 2
#include "ParticleStep.glsl"
