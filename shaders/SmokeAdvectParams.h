/* SmokeAdvectParams.h: push constants and emitter records of smoke_advect.comp, shared by C++
   and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks, so glslang reads it too).
   Scalars only, padded to multiples of 16 bytes, so the std430 layouts and the C++ layouts agree.
   CPU reference: engine/field/SmokeAdvection. */
#ifndef MODEFLOW_SHADERS_SMOKE_ADVECT_PARAMS_H
#define MODEFLOW_SHADERS_SMOKE_ADVECT_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* What one dispatch of smoke_advect.comp computes (`stage`). */
#define SMOKE_STAGE_SEMI_LAGRANGIAN 0u   /* out = SL(in) + emitters */
#define SMOKE_STAGE_MACCORMACK_FORWARD 1u  /* hat = SL(in) */
#define SMOKE_STAGE_MACCORMACK_CORRECT 2u  /* out = clamp(hat + (in - SL_-dt(hat)) / 2) + emitters */

struct SmokeAdvectParams {
    uint cellsX; /* smoke grid cells per axis (1 on the unused axis of a 2D grid) */
    uint cellsY;
    uint cellsZ;
    uint cellCount;
    uint basisX; /* basis (velocity) grid cells per axis */
    uint basisY;
    uint basisZ;
    uint dim;
    uint faceOffsetY; /* number of the first normal-y and normal-z face (MacGrid::faceOffset) */
    uint faceOffsetZ;
    uint scale; /* smoke cells per basis cell along each used axis */
    uint stage;
    uint firstCell; /* this dispatch handles cells firstCell ... firstCell + invocations - 1 */
    uint emitterCount;
    uint pad0;
    uint pad1;
    float stepX; /* dt / smoke spacing per axis (0 on an unused axis): velocity to cells per step */
    float stepY;
    float stepZ;
    float dt;
    float originX; /* smoke grid box corner and spacing, for the emitters' world coordinates */
    float originY;
    float originZ;
    float pad2;
    float spacingX;
    float spacingY;
    float spacingZ;
    float pad3;
};

#define SMOKE_EMITTER_BALL 0u
#define SMOKE_EMITTER_BOX 1u

/* One engine/field/SmokeEmitter in float32. */
struct SmokeEmitterData {
    float centreX;
    float centreY;
    float centreZ;
    float radius;
    float minX;
    float minY;
    float minZ;
    float densityRate;
    float maxX;
    float maxY;
    float maxZ;
    float temperatureRate;
    uint shape;
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifdef __cplusplus
static_assert(sizeof(SmokeAdvectParams) == 112, "push constants are scalars padded to 16 bytes");
static_assert(sizeof(SmokeEmitterData) == 64, "emitter records are scalars padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
