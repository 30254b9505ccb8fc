#version 450
// The first pass of the contraction's combine (ModalCombine.glsl): out = U b.
#extension GL_GOOGLE_include_directive : require
#include "ModalCombine.glsl"
