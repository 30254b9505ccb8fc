/* ParticleStepParams.h: push constants and set records of particle_step_{2d,3d}.comp, shared by
   C++ and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_PARTICLE_STEP_PARAMS_H
#define MODEFLOW_SHADERS_PARTICLE_STEP_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* The stages of a step, the kernel's specialization constant 2. */
/* every particle carried by the air; those then within reach of a solid listed, the rest
   finished */
#define PARTICLE_STEP_MOVE 0u
/* one invocation: the next stages' indirect dispatch arguments from the lists' lengths */
#define PARTICLE_STEP_ARGS 1u
/* the particles near a solid: those in one listed, the rest finished */
#define PARTICLE_STEP_NEAR 2u
/* the particles in a solid pushed out of the solids, then finished */
#define PARTICLE_STEP_INSIDE 3u

/* A set's response over the step (engine/simulation/ParticleMotion.h). */
struct ParticleSetRecord {
    uint inertial; /* 0: a tracer */
    float decay;   /* exp(-drag dt) */
    float reach;   /* (1 - exp(-drag dt)) / drag */
    float fall;    /* gravity / drag */
};

struct ParticleStepParams {
    uint count; /* particles */
    uint obstacleCount;
    uint boundary;     /* MacGrid::boundaryBits: periodic axes, sides the air flows through */
    uint allFluid;     /* every smoke cell is fluid: no slide along walls */
    uint cells[3];     /* basis grid */
    uint up;           /* the buoyancy axis */
    uint faceStart[3]; /* first face of each normal axis */
    float dt;
    float origin[3];
    float margin; /* past a solid's surface */
    float spacing[3];
    uint first; /* the dispatch's first particle */
    uint smokeCells[3];
    uint openSides; /* MacGrid::crossableSideBits: bit 2 axis + (0 low, 1 high), the air crosses
                       that side (open, or a wind's) and what it carries across leaves */
    float smokeSpacing[3];
    uint maxGroups; /* the device's maxComputeWorkGroupCount[0] */
};

#ifdef __cplusplus
static_assert(sizeof(ParticleSetRecord) == 16 && sizeof(ParticleStepParams) == 112,
              "std430 and C++ layouts agree");
} /* namespace modeflow::shaders */
#endif

#endif
