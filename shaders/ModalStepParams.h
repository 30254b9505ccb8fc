/* ModalStepParams.h: push constants of the modal step kernels (modal_pair_sums.comp,
   modal_pair_sums_sparse.comp, modal_combine.comp, modal_update.comp), shared by C++ and GLSL
   (ASCII, no C++-only syntax outside the __cplusplus blocks, so glslang reads it too). Each is
   padded to a multiple of 16 bytes so the std430 push-constant layout and the C++ layout agree. */
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
    uint rowOctets; /* 8-float octets per row: N rounded up to a multiple of 8, over 8 (zero-padded)
                     */
    uint firstPair;
    uint pairCount;
    uint n;
};

/* The sparse rows: rowCount rows of entries, each row one pair k < j (sliced:
 * modal_pair_sums_sparse.comp). */
struct SparsePairSumsParams {
    uint n;
    uint rowCount;
    uint rowFloats; /* floats per row of the pair-sum matrix (modal_combine.comp) */
    uint pad0;
};

/* modal_combine.comp: N outputs; modal_pair_sums*.comp write the N x N matrix of pair sums, rows
   of rowTexels texels (4 floats each: N padded as a modal vector). */
struct CombineParams {
    uint n;
    uint rowTexels;
    uint pad0;
    uint pad1;
};

/* The Lie advection out_i = sum_kj C[k][i][j] u_k x_j of a stored tensor (MHD's induction term,
   engine/device/DeviceCoefficients::recordAdvect). Dense: the pair weights w(k,j) = u_k x_j -
   u_j x_k (modal_pair_weights.comp), then per chunk partial sums over groups of tiles
   (modal_advect_dense.comp), then their sum (modal_advect_sum.comp). Sparse: one gather per i over
   the entries of column i (modal_advect_sparse.comp). */
struct AdvectDenseParams {
    uint rowOctets; /* as PairSumsParams */
    uint firstPair;
    uint pairCount;
    uint firstGroup;    /* the chunk's first row of partial sums */
    uint tilesPerGroup; /* tiles each group sums */
    uint groupCount;    /* the chunk's groups */
    uint pad0;
    uint pad1;
};

struct AdvectSumParams {
    uint n;
    uint groupCount; /* rows of partial sums, over all chunks */
    uint rowStride;  /* floats per row of partial sums (8 rowOctets) */
    uint pad0;
};

/* What modal_update.comp does with r = R(y) from modal_combine.comp (formulas in the shader). */
#define MODAL_OP_BEGIN                                                                        \
    0u /* half decay of x, y = x (midpoint: or a warm start from the r held), arguments reset \
          (the predictor's switched off while a linearized rate is held) */
#define MODAL_OP_EXPLICIT 1u     /* x += h M^-1 (r + f), half decay */
#define MODAL_OP_RK4_STAGE 2u    /* stage `stage` (0..3) of classical RK4 */
#define MODAL_OP_MIDPOINT 3u     /* one fixed-point iteration of the midpoint rule */
#define MODAL_OP_MIDPOINT_END 4u /* x = 2 y - x, half decay; no r */
#define MODAL_OP_TRAPEZOIDAL_START \
    5u                          /* r0 = R(x) kept, y = x + h M^-1 (r0 + f) (explicit predictor) */
#define MODAL_OP_TRAPEZOIDAL 6u /* one fixed-point iteration of the trapezoidal rule */
#define MODAL_OP_TRAPEZOIDAL_END 7u /* x = y, half decay; no r */
#define MODAL_OP_LINEARIZED_START                                                            \
    8u /* y = x + h/2 (g + M^-1 f) with the rate held, or g = M^-1 R(x) from r; a = M y (the \
          predictor the iterations freeze) */
#define MODAL_OP_LINEARIZED_END \
    9u /* as MIDPOINT_END; the rate g = 2 (y - x) / h - M^-1 f held; no step-end R held */
/* Directions of the implicit iterations' Anderson acceleration (modal_update.comp): its history
   holds 2 ANDERSON_DEPTH + 2 state-sized vectors, one for the warm start and one for the
   linearized rule's held rate. */
#define ANDERSON_DEPTH 5

/* The operation, the linearized rule's frozen point and MHD's Lorentz force are specialization
   constants of modal_update.comp, not push constants (why: there). */
struct ModalUpdateParams {
    uint n;
    uint stage;          /* RK4 stage */
    uint argumentCount;  /* indirect dispatches the implicit iterations switch off */
    uint predictorCount; /* indirect dispatches of the linearized predictor's R(x), after the
                            iterations' two copies: switched off while a rate is held */
    float h;             /* step */
    float tolerance; /* implicit rules: relative max-norm change of y that counts as converged */
    uint stride;     /* floats per part of the state (n padded) */
    uint parts;      /* 1: the fluid's v; 2: MHD's [v; F], each part at a multiple of stride */
    uint anderson;   /* implicit rules: 1 accelerates the fixed-point iteration */
    uint warm;       /* BEGIN of a midpoint step: 1 starts from the R held, if any */
    uint pad0;
    uint pad1;
    uint pad2;
    uint pad3;
    uint pad4;
    uint pad5;
};

/* The status block modal_update.comp keeps for the host. */
struct ModalStatus {
    uint iterations;  /* implicit (midpoint, trapezoidal) iterations of the current (last) step */
    uint unconverged; /* implicit steps so far that hit the iteration limit */
    float residual;   /* last relative change of y */
    uint converged;   /* 1 once the current step's iteration converged */
    uint heldRhs;     /* R at the ends of the last 0-2 converged implicit steps held (r, history) */
    uint heldRate;    /* 1: the linearized rule's rate g held (history slot 2 ANDERSON_DEPTH + 3) */
    uint pad1;
    uint pad2;
};

#ifdef __cplusplus
static_assert(sizeof(PairSumsParams) == 16 && sizeof(SparsePairSumsParams) == 16 &&
                  sizeof(CombineParams) == 16 && sizeof(AdvectDenseParams) == 32 &&
                  sizeof(AdvectSumParams) == 16 && sizeof(ModalUpdateParams) == 64 &&
                  sizeof(ModalStatus) == 32,
              "push constants are padded to 16 bytes");
} /* namespace modeflow::shaders */
#endif

#endif
