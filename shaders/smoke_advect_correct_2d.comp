#version 450
// MacCormack's correction on a 2D smoke grid: SmokeAdvect.glsl with its stage and dimension fixed
// at compile time (why: SmokeAdvect.glsl).
#extension GL_GOOGLE_include_directive : require
#include "SmokeAdvectParams.h"
#define SMOKE_DIM 2
#define SMOKE_STAGE SMOKE_STAGE_MACCORMACK_CORRECT
#include "SmokeAdvect.glsl"
