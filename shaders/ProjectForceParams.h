/* ProjectForceParams.h: push constants of project_force.comp (partial sums) and
   project_force_sum.comp (their total), shared by C++ and GLSL (ASCII, no C++-only syntax outside
   the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_PROJECT_FORCE_PARAMS_H
#define MODEFLOW_SHADERS_PROJECT_FORCE_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* The tiles of engine/device/ModeBuffer (kTileLanes, kTileRows), see ModeAccess.glsl. */
#define MODE_TILE_LANES 8
#define MODE_TILE_ROWS 2

/* The most modes one workgroup of the partial-sum pass handles (a multiple of 4; the pipeline's
   count, specialization constant MODES, is at most this). */
#define PROJECT_FORCE_MODES_PER_GROUP 64

struct ProjectForceParams {
    uint dofCount;   /* velocity DOFs */
    uint firstMode;  /* the chunk's first mode: row of the partial sums */
    uint modeCount;  /* modes in the chunk */
    uint tileCount;  /* tiles per mode (ModeAccess.glsl) */
    uint blockCount; /* DOF blocks, one partial sum per mode and block */
    uint blockTiles; /* tiles per block */
    uint pad0;
    uint pad1;
};

struct ProjectForceSumParams {
    uint modeCount;  /* N: one invocation per mode */
    uint blockCount; /* partial sums per mode */
    uint pad0;
    uint pad1;
};

#ifdef __cplusplus
static_assert(sizeof(ProjectForceParams) == 32, "push constants are padded to 16 bytes");
static_assert(sizeof(ProjectForceSumParams) == 16, "push constants are padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
