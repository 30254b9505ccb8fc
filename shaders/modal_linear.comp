#version 450
// A constant linear term of the right-hand side (ModalCombine.glsl): out += D b, D dense.
#extension GL_GOOGLE_include_directive : require
#define DENSE_ADD
#include "ModalCombine.glsl"
