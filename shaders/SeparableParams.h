/* SeparableParams.h: push constants of the closed-form basis transforms (separable_pass.comp,
   separable_gather.comp; engine/device/SeparableTransform), shared by C++
   and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_SEPARABLE_PARAMS_H
#define MODEFLOW_SHADERS_SEPARABLE_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* Blocks of four outputs one invocation of separable_pass.comp computes. */
#define SEPARABLE_BLOCKS_PER_INVOCATION 2u

/* Index of a gather term that adds nothing. */
#define SEPARABLE_NONE 0xFFFFFFFFu

/* One pass along one axis: lines of inLength values (fastest) in d1 x d2 of them, each taken
   through the outLength x inLength table (stored j-major in texels: separable_pass.comp); the
   output has the axes rotated (d1 fastest, d2, then outLength), its rows of d1 values outRow
   apart and its planes of d2 rows outPlane apart (d1 and d1 d2 for a packed tensor; the last
   pass of a reconstruction writes straight into the face field's rows and planes). */
struct SeparablePassParams {
    uint d1;
    uint d2;
    uint inLength;
    uint outLength;
    uint inOffset;   /* first value of the input tensor in its buffer */
    uint outOffset;  /* first value of the output tensor in its buffer */
    uint tableTexel; /* first texel of the table in the tables buffer */
    uint outRow;     /* values between the starts of two output rows (i2 -> i2 + 1) */
    uint outPlane;   /* values between the starts of two output planes (q -> q + 1) */
    /* The window of lines and inputs the pass takes, the other inputs being 0 (a projection of
       a field that vanishes outside a box of cells): lines i1 in [i1First, i1First + i1Count),
       i2 in [i2First, i2First + i2Count), inputs j in [jFirst, jFirst + jCount). The lines
       outside are not written: the next pass's window reads none of them. The whole tensor:
       0, d1, 0, d2, 0, inLength. */
    uint i1First;
    uint i1Count;
    uint i2First;
    uint i2Count;
    uint jFirst;
    uint jCount;
    /* The outputs q in [outFirst, outFirst + outCount) at least (a reconstruction needed only on
       a box of cells; those outside may be written too). All: 0, outLength. */
    uint outFirst;
    uint outCount;
    uint pad0;
    uint pad1;
    uint pad2;
};

/* out[outOffset + e] = sum over t < terms of weight[e terms + t] in[index[e terms + t]], for
   e < count (indices SEPARABLE_NONE add nothing). */
struct SeparableGatherParams {
    uint count;
    uint terms;
    uint outOffset;
    uint pad0;
};

#ifdef __cplusplus
static_assert(sizeof(SeparablePassParams) == 80, "push constants are padded to 16 bytes");
static_assert(sizeof(SeparableGatherParams) == 16, "push constants are padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
