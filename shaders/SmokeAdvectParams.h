/* SmokeAdvectParams.h: push constants of smoke_face_pairs.comp and the smoke_advect_* kernels, and
   the layout of the buffers SmokeState keeps for them, shared by C++ and GLSL (ASCII, no C++-only
   syntax outside the __cplusplus blocks, so glslang reads it too). Scalars only, padded to
   multiples of 16 bytes, so the std430 layouts and the C++ layouts agree.
   CPU reference: engine/reference/reference::SmokeAdvection. */
#ifndef MODEFLOW_SHADERS_SMOKE_ADVECT_PARAMS_H
#define MODEFLOW_SHADERS_SMOKE_ADVECT_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* What one smoke_advect kernel computes (SMOKE_STAGE, fixed at compile time). */
#define SMOKE_STAGE_SEMI_LAGRANGIAN 0    /* out = SL(in) + emitters */
#define SMOKE_STAGE_MACCORMACK_FORWARD 1 /* hat = SL(in), and the record of the cell */
#define SMOKE_STAGE_MACCORMACK_CORRECT                        \
    2 /* out = clamp(hat + (in - SL_-dt(hat)) / 2) + emitters \
       */

/* A fluid cell of the list the advection runs over: one 16-byte texel, x | y << 16 (so at most
   65535 cells along x and y), z, and the cell's emitters' density and temperature rates (floats).
 */
#define SMOKE_CELL_AXIS_LIMIT 65535u

/* The stencil mask: one byte per cell, 4 to a 32-bit word (a texel of its R32UI view); bit
   cx + 2 cy + 4 cz of the byte of cell (i, j, k) is set when cell (i + cx, j + cy, k + cz) exists
   and is fluid (taken across the seam along a periodic axis), so one load gives the fluid flags
   of a whole trilinear stencil whose low corner is (i, j, k). */

/* MacCormack's record of a fluid cell (list order), written by the forward stage for the
   correction: 64-bit words (lo.density, lo.temperature), (hi.density, hi.temperature) over the
   fluid cells of the forward stencil (lo > hi: none), then the backward trace's end point
   (x, y) and, in 3D, (z, 0): two texels, which the correction fetches. */
#define SMOKE_RECORD_WORDS 4u

/* Bits of SmokeAdvectParams::boundary: a side across axis a where the wind brings in clean air
   (engine/reference/SmokeAdvection.h: ghost cells half a cell out hold 0). */
#define SMOKE_INFLOW_LOW 6u
#define SMOKE_INFLOW_HIGH 9u

struct SmokeAdvectParams {
    uint cellsX; /* smoke grid cells per axis (1 on the unused axis of a 2D grid) */
    uint cellsY;
    uint cellsZ;
    uint fluidCount; /* entries of the fluid cell list */
    uint basisX;     /* basis (velocity) grid cells per axis */
    uint basisY;
    uint basisZ;
    uint scale;       /* smoke cells per basis cell along each used axis */
    uint faceOffsetY; /* number of the first normal-y and normal-z face (MacGrid::faceOffset) */
    uint faceOffsetZ;
    uint firstCell; /* this dispatch handles list entries firstCell ... firstCell + invocations - 1
                     */
    uint boundary;  /* MacGrid::boundaryBits of the basis grid (periodic axes, both grids; sides
                       the air flows through), and the smoke's inflow sides: bit
                       SMOKE_INFLOW_LOW + a (the low side across axis a) and SMOKE_INFLOW_HIGH + a */
    float stepX; /* dt / smoke spacing per axis (0 on an unused axis): velocity to cells per step */
    float stepY;
    float stepZ;
    float dt;
    uint ghostPair; /* the fields of the ghosts (binding 8, OutsideAir) this pair reads: 0 its
                       (density, temperature), 1 its (fuel, 0) */
    uint pad2;
    uint pad0;
    uint pad1;
};

struct SmokeFacePairsParams {
    uint faceCount; /* MacGrid::faceTotal of the basis grid */
    uint firstFace; /* a multiple of 4: this dispatch handles faces firstFace ... firstFace + 4
                       invocations - 1 */
    uint wrapX;     /* x periodic: the basis grid's cells along x, every face group's row length
                       (the last face of a row pairs with the row's first); 0 otherwise */
    uint pad1;
};

#ifdef __cplusplus
static_assert(sizeof(SmokeAdvectParams) == 80, "push constants are scalars padded to 16 bytes");
static_assert(sizeof(SmokeFacePairsParams) == 16, "push constants are scalars padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
