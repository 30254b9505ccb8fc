/* ModeAccess.glsl: the stored values of a chunk of modes uploaded by engine/device/ModeBuffer,
   read as 32-byte words of 8 float32 DOFs or 16 float16 DOFs (DOFs 2w and 2w+1 in 32-bit half-word
   w, the even one in the low half, as unpackHalf2x16 returns it in .x), each word two of
   ModeBuffer's 16-byte vectors, fetched as two texels (TexelAccess.glsl). The stored values still
   need the mode's scale factor. The includer defines MODE_TILE_LANES and MODE_TILE_ROWS (its
   params header; engine/device/ModeBuffer's kTileLanes and kTileRows = 2, the 16-byte vectors of
   a word) and declares `uniform usamplerBuffer modeTexels` (the chunk) first.

   Layout: tile-major. Each mode is cut into tiles of MODE_TILE_LANES words; the chunk holds tile 0
   of each of its modes, then tile 1 of each, and so on. A "unit" is one invocation's share of a
   tile: unit u reads, of every mode, word u % MODE_TILE_LANES of tile u / MODE_TILE_LANES, which
   is word u of the mode (DOFs 8u ... 8u + 7 in float32, 16u ... 16u + 15 in float16).

   Why, measured on lavapipe (Mesa 22.3, LLVM 15; tools/bench/bench_runtime and profiles of the
   JIT code): each lane's storage-buffer load is a scalar load of its own per component, wrapped in
   mask and bounds checks, in a loop over the lanes, so a load costs about the same whatever it
   brings, and a cache miss its full latency unless the prefetcher has fetched the line. Mode-major
   modes summed per invocation jump to another mode at every load, and the prefetcher loses track:
   a probe kernel streaming the same bytes that way ran several times slower than contiguously.
   Tiles make what one 8-wide batch of invocations (lavapipe's SIMD width with AVX2) reads of all
   the modes one contiguous stream, which made the reconstruction several times faster
   (reconstruct_velocity.comp). Texel fetches, vector gathers on lavapipe, then read that stream
   faster still than 32-byte storage loads (engine/README.md "Speed"). On a GPU each fetch of a
   warp covers whole, aligned segments (a tile: 8 neighbouring invocations x 32 bytes). */
#ifndef MODEFLOW_SHADERS_MODE_ACCESS_GLSL
#define MODEFLOW_SHADERS_MODE_ACCESS_GLSL

#if MODE_TILE_ROWS != 2
#error "a word is two 16-byte vectors (two texels)"
#endif

#include "TexelAccess.glsl"
const uint TILE_LANES = MODE_TILE_LANES;
const uint TILE_ROWS = MODE_TILE_ROWS;  // 16-byte vectors per word

/* Word `word` of the chunk as 8 float32 values (a: the first four) or 16 float16 values (a, b:
   the first eight, c, d: the last). */
void modeFloats(uint word, out vec4 a, out vec4 b) {
    a = floatTexel(modeTexels, 2u * word);
    b = floatTexel(modeTexels, 2u * word + 1u);
}
void modeHalves(uint word, out vec4 a, out vec4 b, out vec4 c, out vec4 d) {
    halfTexel(modeTexels, 2u * word, a, b);
    halfTexel(modeTexels, 2u * word + 1u, c, d);
}

/* Index of unit `unit`'s word of the chunk's mode 0 (add mode * TILE_LANES for mode `mode`); the
   chunk holds `modeCount` modes. */
uint unitBase(uint unit, uint modeCount) {
    return (unit / TILE_LANES) * modeCount * TILE_LANES + unit % TILE_LANES;
}

/* The units of tiles tileBegin ... tileEnd - 1 that invocation `index` of `count` takes: begin,
   begin + step, ... below end. With whole batches of TILE_LANES invocations each batch takes a run
   of consecutive tiles: on lavapipe a batch is the SIMD width, and its loads then advance by a
   fixed stride the prefetcher follows. Otherwise the invocations stride over the units. */
void unitRange(uint index, uint count, uint tileBegin, uint tileEnd, out uint begin, out uint step, out uint end) {
    begin = tileBegin * TILE_LANES + index;
    step = count;
    end = tileEnd * TILE_LANES;
    if (count % TILE_LANES == 0u) {
        const uint tiles = tileEnd - tileBegin, batches = count / TILE_LANES;
        const uint perBatch = (tiles + batches - 1u) / batches, first = min((index / TILE_LANES) * perBatch, tiles);
        begin = (tileBegin + first) * TILE_LANES + index % TILE_LANES;
        step = TILE_LANES;
        end = (tileBegin + min(first + perBatch, tiles)) * TILE_LANES;
    }
}

#endif
