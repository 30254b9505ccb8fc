/* SmokeFluxParams.h: push constants of the smoke_flux_* kernels (the conservative smoke
   transport on the device, engine/device/ConservativeTransport.h), shared by C++ and GLSL (ASCII,
   no C++-only syntax outside the __cplusplus blocks). Scalars only, padded to multiples of 16
   bytes, so the std430 layouts and the C++ layouts agree.
   CPU reference: engine/reference/ConservativeTransport. */
#ifndef MODEFLOW_SHADERS_SMOKE_FLUX_PARAMS_H
#define MODEFLOW_SHADERS_SMOKE_FLUX_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

struct SmokeFluxParams {
    uint cellsX; /* smoke grid cells per axis (1 on the unused axis of a 2D grid) */
    uint cellsY;
    uint cellsZ;
    uint dim;
    uint basisX; /* basis (velocity) grid cells per axis */
    uint basisY;
    uint basisZ;
    uint scale;       /* smoke cells per basis cell along each used axis */
    uint faceOffsetY; /* the basis grid's first normal-y and normal-z face (MacGrid::faceOffset) */
    uint faceOffsetZ;
    uint smokeFaceOffsetY; /* the smoke grid's */
    uint smokeFaceOffsetZ;
    uint boundary;  /* MacGrid::boundaryBits of the basis grid with the smoke's inflow sides
                       (SmokeAdvectParams.h's SMOKE_INFLOW_* bits) */
    uint crossable; /* MacGrid::crossableSideBits of the basis grid: sides the air crosses */
    uint first;     /* this dispatch handles invocations first ... first + invocations - 1 */
    uint count;     /* invocations in all: faces, cells or fluid cells */
    float spacingX; /* smoke cell size per axis (1 on an unused axis) */
    float spacingY;
    float spacingZ;
    float dt;
    float substep;  /* dt / substeps */
    uint ghostPair; /* the ghosts' fields this pair reads: 0 (density, temperature), 1 (fuel, 0) */
    uint last;      /* the step's last substep: add the emitters' rates times dt, write the second
                       field alone */
    uint pad0;
};

#ifdef __cplusplus
static_assert(sizeof(SmokeFluxParams) == 96, "push constants are scalars padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
