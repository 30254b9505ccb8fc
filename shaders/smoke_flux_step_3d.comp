#version 450
// The conservative smoke transport's step stage on a 3D smoke grid: SmokeFlux.glsl with its
// stage and dimension fixed at compile time.
#extension GL_GOOGLE_include_directive : require
#define SMOKE_DIM 3
#define SMOKE_FLUX_STAGE 2
#include "SmokeFlux.glsl"
