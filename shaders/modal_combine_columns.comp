#version 450
// The second pass of the contraction's combine (ModalCombine.glsl): out -= U^T b.
#extension GL_GOOGLE_include_directive : require
#define COMBINE_COLUMNS
#include "ModalCombine.glsl"
