/* ModeAccess.glsl: one stored value of a chunk of modes uploaded by engine/kernels/ModeBuffer:
   mode-major, `stride` 32-bit words per mode, float32 words or float16 pairs (DOFs 2w and 2w+1
   in word w, the even one in the low half, as unpackHalf2x16 returns it in .x). The stored values
   still need the mode's scale factor. The includer declares `uint modeWords[]` (the chunk) first. */
#ifndef MODEFLOW_SHADERS_MODE_ACCESS_GLSL
#define MODEFLOW_SHADERS_MODE_ACCESS_GLSL

float modeValue32(uint mode, uint dof, uint stride) { return uintBitsToFloat(modeWords[mode * stride + dof]); }

float modeValue16(uint mode, uint dof, uint stride) {
    const vec2 pair = unpackHalf2x16(modeWords[mode * stride + (dof >> 1)]);
    return (dof & 1u) == 0u ? pair.x : pair.y;
}

float modeValue(uint mode, uint dof, uint stride, bool halfPrecision) {
    return halfPrecision ? modeValue16(mode, dof, stride) : modeValue32(mode, dof, stride);
}

#endif
