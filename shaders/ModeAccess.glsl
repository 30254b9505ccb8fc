/* ModeAccess.glsl: the stored values of a chunk of modes uploaded by engine/kernels/ModeBuffer
   (and float arrays read four at a time) as 16-byte vectors: 4 float32 DOFs, or 8 float16 DOFs
   (DOFs 2w and 2w+1 in 32-bit word w, the even one in the low half, as unpackHalf2x16 returns it
   in .x). The stored values still need the mode's scale factor. The includer enables
   GL_EXT_shader_explicit_arithmetic_types_int64, defines MODE_TILE_LANES and MODE_TILE_ROWS (its
   params header; engine/kernels/ModeBuffer's kTileLanes and kTileRows) and declares
   `u64vec2 modeVectors[]` (the chunk) first.

   Layout: tile-major. Each mode is cut into tiles of MODE_TILE_LANES x MODE_TILE_ROWS vectors; the
   chunk holds tile 0 of each of its modes, then tile 1 of each, and so on. A "unit" is one
   invocation's share of a tile: unit u reads, of every mode, the vectors
   r * MODE_TILE_LANES + u % MODE_TILE_LANES (r < MODE_TILE_ROWS) of tile u / MODE_TILE_LANES.

   Why, measured on lavapipe (Mesa 22.3, LLVM 15; tools/bench/bench_runtime and profiles of the
   JIT code): each lane's load is a scalar load of its own, wrapped in mask and bounds checks, and
   nearly serial (the address vector is spilled and reloaded per lane), so a load costs the same
   whatever it brings, and a cache miss its full latency unless the prefetcher has fetched the
   line. 64-bit components bring 4 floats (8 halves) per lane and u64vec2 load; u64vec4 is split
   into two. Mode-major modes summed per invocation jump to another mode at every load, and the
   prefetcher loses track: a probe kernel streaming the same bytes that way ran at 0.75 GB/s,
   contiguously at 3.5-4.4. Tiles make what one 8-wide batch of invocations (lavapipe's SIMD width
   with AVX2) reads of all the modes one contiguous stream: the reconstruction went from 113 to
   32 ms (reconstruct_velocity.comp). On a GPU each load of a warp covers whole, aligned 128-byte
   segments (a tile row of 8 neighbouring invocations). */
#ifndef MODEFLOW_SHADERS_MODE_ACCESS_GLSL
#define MODEFLOW_SHADERS_MODE_ACCESS_GLSL

const uint TILE_LANES = MODE_TILE_LANES;
const uint TILE_ROWS = MODE_TILE_ROWS;
const uint TILE_VECTORS = MODE_TILE_LANES * MODE_TILE_ROWS;

/* Four float32 values stored in one 16-byte vector. */
vec4 floatsOf(u64vec2 vector) {
    return vec4(uintBitsToFloat(unpack32(vector.x)), uintBitsToFloat(unpack32(vector.y)));
}

/* Eight float16 values stored in one 16-byte vector: the first four in `low`, the last in `high`. */
void halvesOf(u64vec2 vector, out vec4 low, out vec4 high) {
    const uvec2 a = unpack32(vector.x), b = unpack32(vector.y);
    low = vec4(unpackHalf2x16(a.x), unpackHalf2x16(a.y));
    high = vec4(unpackHalf2x16(b.x), unpackHalf2x16(b.y));
}

/* Index of unit `unit`'s row-0 vector of the chunk's mode 0 (add mode * TILE_VECTORS for mode
   `mode`, r * TILE_LANES for row r); the chunk holds `modeCount` modes. */
uint unitBase(uint unit, uint modeCount) {
    return (unit / TILE_LANES) * modeCount * TILE_VECTORS + unit % TILE_LANES;
}

/* Index i, within one mode, of unit `unit`'s row-r vector: it holds DOFs 4i ... 4i + 3 (float32)
   or 8i ... 8i + 7 (float16). */
uint unitVector(uint unit, uint r) { return (unit / TILE_LANES) * TILE_VECTORS + r * TILE_LANES + unit % TILE_LANES; }

#endif
