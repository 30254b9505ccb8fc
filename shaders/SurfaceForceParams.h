/* SurfaceForceParams.h: push constants of a surface's stirring force (surface_splat_vertices.comp,
   surface_splat_project.comp; engine/device/SurfaceForce.h), shared by C++ and GLSL (ASCII, no
   C++-only syntax outside the __cplusplus blocks); padded to 16 bytes, so the std430 and C++
   layouts agree. */
#ifndef MODEFLOW_SHADERS_SURFACE_FORCE_PARAMS_H
#define MODEFLOW_SHADERS_SURFACE_FORCE_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

struct SurfaceSplatParams {
    uint vertexCount;
    uint splatCount;
    uint n;         /* velocity modes (the projection) */
    uint rowFloats; /* 3 vertexCount: a mode's velocity at every vertex */
};

#ifdef __cplusplus
static_assert(sizeof(SurfaceSplatParams) == 16, "push constants are scalars padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
