/* ModalStepParams.h: push constants of the modal step kernels (modal_pair_sums.comp,
   modal_pair_sums_sparse.comp, modal_combine.comp, modal_update.comp), shared by C++ and GLSL (ASCII, no C++-only
   syntax outside the __cplusplus blocks, so glslang reads it too). Each is padded to a multiple of
   16 bytes so the std430 push-constant layout and the C++ layout agree. */
#ifndef MODEFLOW_SHADERS_MODAL_STEP_PARAMS_H
#define MODEFLOW_SHADERS_MODAL_STEP_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* The dense coefficients' tiles (modal_pair_sums.comp, engine/device/DeviceCoefficients): rows
   per tile, and invocations that share one (lavapipe's SIMD width with AVX2). */
#define PAIR_TILE_LANES 8
#define PAIR_TILE_ROWS 64

/* One chunk of the dense packed coefficients: rows (pairs k < j) firstPair ... firstPair +
   pairCount - 1, each N floats (engine/core/PackedLayout.h), in tiles of PAIR_TILE_ROWS rows. */
struct PairSumsParams {
    uint rowOctets;  /* 8-float octets per row: N rounded up to a multiple of 8, over 8 (zero-padded) */
    uint firstPair;
    uint pairCount;
    uint pad0;
};

/* The sparse rows: rowCount rows of entries, each row one pair k < j (sliced:
 * modal_pair_sums_sparse.comp). */
struct SparsePairSumsParams {
    uint n;
    uint rowCount;
    uint pad0;
    uint pad1;
};

/* modal_combine.comp: N outputs. */
struct CombineParams {
    uint n;
    uint pad0;
    uint pad1;
    uint pad2;
};

/* What modal_update.comp does with r = R(y) from modal_combine.comp (formulas in the shader). */
#define MODAL_OP_BEGIN 0u        /* half decay of x, y = x, arguments reset; no r */
#define MODAL_OP_EXPLICIT 1u     /* x += h M^-1 (r + f), half decay */
#define MODAL_OP_RK4_STAGE 2u    /* stage `stage` (0..3) of classical RK4 */
#define MODAL_OP_MIDPOINT 3u     /* one fixed-point iteration of the midpoint rule */
#define MODAL_OP_MIDPOINT_END 4u /* x = 2 y - x, half decay; no r */

struct ModalUpdateParams {
    uint n;
    uint op;
    uint stage;          /* RK4 stage */
    uint argumentCount;  /* indirect dispatches the midpoint iterations switch off */
    float h;             /* step */
    float tolerance;     /* midpoint: relative max-norm change of y that counts as converged */
    uint pad0;
    uint pad1;
};

/* The status block modal_update.comp keeps for the host. */
struct ModalStatus {
    uint iterations;   /* midpoint iterations of the current (last) step */
    uint unconverged;  /* midpoint steps so far that hit the iteration limit */
    float residual;    /* last relative change of y */
    uint converged;    /* 1 once the current step's iteration converged */
};

#ifdef __cplusplus
static_assert(sizeof(PairSumsParams) == 16 && sizeof(SparsePairSumsParams) == 16 && sizeof(CombineParams) == 16 &&
              sizeof(ModalUpdateParams) == 32 && sizeof(ModalStatus) == 16,
              "push constants are padded to 16 bytes");
}  /* namespace modeflow::shaders */
#endif

#endif
