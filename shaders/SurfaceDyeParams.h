/* SurfaceDyeParams.h: push constants of the surface dye kernels (surface_dye_pairs.comp,
   surface_dye_step.comp; engine/device/SurfaceDye.h), shared by C++ and GLSL (ASCII, no C++-only
   syntax outside the __cplusplus blocks); padded to 16 bytes, so the std430 and C++ layouts
   agree. */
#ifndef MODEFLOW_SHADERS_SURFACE_DYE_PARAMS_H
#define MODEFLOW_SHADERS_SURFACE_DYE_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* pairs[p] = sum_m A[p][m] (v0_m + v1_m) / 2 over the velocity modes m < n: one value per scalar
   pair i < j (engine/core/PackedLayout.h's order), A stored by columns of columnTexels texels. */
struct SurfaceDyePairsParams {
    uint pairCount;
    uint n;
    uint columnTexels; /* pairCount rounded up to a multiple of 4, over 4 */
    uint pad0;
};

/* One Cayley step of the dye's M scalar amplitudes (the file comment of surface_dye_step.comp). */
struct SurfaceDyeStepParams {
    uint m;             /* scalar modes */
    uint maxIterations; /* of the conjugate gradients */
    float h;            /* the step */
    float tolerance;    /* relative residual of the normal equations that counts as solved */
};

/* What surface_dye_step.comp leaves for the host after a step. */
struct SurfaceDyeStatus {
    uint iterations;
    uint converged; /* 1 when the residual met the tolerance */
    float residual; /* relative residual reached */
    uint pad0;
};

#ifdef __cplusplus
static_assert(sizeof(SurfaceDyePairsParams) == 16 && sizeof(SurfaceDyeStepParams) == 16 &&
                  sizeof(SurfaceDyeStatus) == 16,
              "push constants are scalars padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
