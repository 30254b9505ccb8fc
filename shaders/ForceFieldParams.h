/* ForceFieldParams.h: push constants and the splat record of force_field.comp, shared by C++
   and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks). Scalars and scalar arrays
   only, so std430 and C++ agree; padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_FORCE_FIELD_PARAMS_H
#define MODEFLOW_SHADERS_FORCE_FIELD_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* One stirring splat (engine/reference/ForceField.h ForceSplat) as float32: 32 bytes. */
struct ForceSplatRecord {
    float centre[3];
    float radius;
    float force[3];
    float pad0;
};

/* force_field.comp's stages (its specialization constant STAGE). */
#define FORCE_STAGE_SPLATS 0u
#define FORCE_STAGE_BUOYANCY 1u

struct ForceFieldParams {
    uint dofCount;   /* velocity DOFs; one invocation per DOF (grid-stride loop) */
    uint upCount;    /* entries of the up-DOF list (the buoyancy stage) */
    uint periodic;   /* bit a: axis a is periodic (MacGrid::periodic) */
    uint splatCount; /* splats in the splat buffer */
    uint cells[3];   /* basis grid cells per axis (1 on the unused 2D axis) */
    uint pad1;
    uint faceStart1; /* first normal-y face */
    uint faceStart2; /* first normal-z face (the face total in 2D) */
    float buoyancy;  /* upward acceleration per unit temperature; 0: no buoyancy */
    uint pad2;
    float origin[3]; /* lower corner of the box */
    float pad3;
    float spacing[3]; /* basis cell size per axis */
    float pad4;
};

#ifdef __cplusplus
static_assert(sizeof(ForceSplatRecord) == 32, "a splat is 32 bytes in std430");
static_assert(sizeof(ForceFieldParams) == 80, "push constants are padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
