/* ReconstructVelocityParams.h: push constants of reconstruct_velocity.comp, shared by C++ and
   GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks). One dispatch per chunk of
   modes (engine/device/ModeBuffer; the chunk's mode count is a specialization constant); padded
   to 16 bytes. */
#ifndef MODEFLOW_SHADERS_RECONSTRUCT_VELOCITY_PARAMS_H
#define MODEFLOW_SHADERS_RECONSTRUCT_VELOCITY_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* The tiles of engine/device/ModeBuffer (kTileLanes, kTileRows), see ModeAccess.glsl. */
#define MODE_TILE_LANES 8
#define MODE_TILE_ROWS 2

struct ReconstructVelocityParams {
    uint dofCount;        /* velocity DOFs */
    uint firstMode;       /* the chunk's first mode: index into v and the mode scales */
    uint tileCount;       /* tiles per mode (ModeAccess.glsl) */
    uint faceStart1;      /* first normal-y face */
    uint faceStart2;      /* first normal-z face (the face total in 2D) */
    float inverseArea[3]; /* 1 / whole face area per normal axis */
    uint pad0;
    uint pad1;
    uint pad2;
    uint pad3;
};

#ifdef __cplusplus
static_assert(sizeof(ReconstructVelocityParams) == 48, "push constants are padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
