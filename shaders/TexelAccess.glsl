/* TexelAccess.glsl: reading a read-only stream bound as a uniform texel buffer (`usamplerBuffer`
   over RGBA32UI texels: engine/vulkan/DeviceBuffer::texelView, ComputeKernelSpec::texelBindings)
   as the floats or float16 pairs its 16 bytes hold.

   Why texels, measured on lavapipe (Mesa 22.3, LLVM 15, AVX2; a probe streaming by 8-lane batches
   reading contiguous runs, engine/README.md "Vulkan runtime"): texel fetches several times faster
   than 32-byte u64vec4 storage-buffer loads. Lavapipe turns a storage-buffer load into a loop over
   the lanes with a mask and bounds check per lane and component; a texel fetch is an unmasked
   vector gather whose out-of-range lanes are selected to zero. On a GPU a texel fetch goes through the texture
   cache, as fast as a load for streams. */
#ifndef MODEFLOW_SHADERS_TEXEL_ACCESS_GLSL
#define MODEFLOW_SHADERS_TEXEL_ACCESS_GLSL

/* Texel `index` as four float32 values. */
vec4 floatTexel(usamplerBuffer texels, uint index) {
    return uintBitsToFloat(texelFetch(texels, int(index)));
}

/* Texel `index` as eight float16 values: the first four in `low`, the last in `high` (the even
   value of a 32-bit word in its low half, as unpackHalf2x16 returns it in .x). */
void halfTexel(usamplerBuffer texels, uint index, out vec4 low, out vec4 high) {
    const uvec4 words = texelFetch(texels, int(index));
    low = vec4(unpackHalf2x16(words.x), unpackHalf2x16(words.y));
    high = vec4(unpackHalf2x16(words.z), unpackHalf2x16(words.w));
}

#endif
