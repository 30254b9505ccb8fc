/* AdvectionParams.h: push constants and layout of the tensor-free advection kernels
   (advection_samples.comp, advection_gather.comp; engine/device/TensorFreeAdvection), shared by
   C++ and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_ADVECTION_PARAMS_H
#define MODEFLOW_SHADERS_ADVECTION_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* What the element kernel forms (specialization constant 1 of advection_samples.comp). */
#define ADVECTION_APPLY 0u  /* (w omega(a) q(b), -w omega(a) p(b)) for C(a, b) */
#define ADVECTION_ADVECT 1u /* (p(u) q(x) - q(u) p(x), 0) for advect(u, x) */

/* Texels (16 bytes) per element in the element table: four face numbers of the curl, two of
   each velocity component, then their eight coefficients (float bits), in that order. */
#define ADVECTION_ELEMENT_TEXELS 4

struct AdvectionSampleParams {
    uint elementCount;
    uint pad0;
    uint pad1;
    uint pad2;
};

struct AdvectionGatherParams {
    uint dofCount;
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifdef __cplusplus
static_assert(sizeof(AdvectionSampleParams) == 16 && sizeof(AdvectionGatherParams) == 16,
              "push constants are padded to 16 bytes");
} /* namespace modeflow::shaders */
#endif

#endif
