/* ObstacleParams.h: the moving-obstacle correction's push constants and obstacle records
   (obstacle_mismatch.comp, modal_correct.comp), shared by C++ and GLSL (ASCII, no C++-only
   syntax outside the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_OBSTACLE_PARAMS_H
#define MODEFLOW_SHADERS_OBSTACLE_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

#define OBSTACLE_BALL 0u
#define OBSTACLE_BOX 1u
#define OBSTACLE_CAPSULE 2u
#define OBSTACLE_MESH 3u
#define OBSTACLE_RIGID 0xffffffffu
/* obstacle_mismatch.comp's DOF of a face that is none. */
#define OBSTACLE_NO_DOF 0xffffffffu
/* The solid kinds a kernel is compiled for (engine/device/SolidKernels.h): bit 1 << shape for
   each shape, and this bit for deforming meshes. */
#define SOLID_KIND_DEFORMING 16u
#define SOLID_KINDS_ALL 31u

/* One obstacle at the step's time (std430: ten vec4s). */
struct ObstacleRecord {
    float centre[3];
    float radius;      /* ball, capsule */
    float halfSize[3]; /* box */
    uint shape;
    float axis[3];         /* capsule: centre to one end of its segment */
    float scale;           /* mesh: world length per mesh unit */
    float velocity[3];     /* of its centre */
    float reach;           /* no point farther than this from its centre is in it */
    float spin[3];         /* angular velocity, rad/s, world frame */
    uint velocityStart;    /* mesh, deforming: its material's velocity in the lattice buffer (xyz
                              per sample, mesh units per unit time); OBSTACLE_RIGID: none */
    float orientation[12]; /* its shape's frame to world: three columns, each xyz and a pad */
    /* mesh: its level set (engine/simulation/SolidLevelSet.h), in the lattice buffer from
       latticeStart, samples x fastest */
    float latticeOrigin[3];
    float latticeSpacing;
    uint latticeSamples[3];
    uint latticeStart;
};

/* obstacle_mismatch.comp walks the faces of a box of cells around the regions (its faces along
   each normal axis), not every face of the grid. */
struct ObstacleMismatchParams {
    uint boxLines[3]; /* lines of faces along x of the box per normal axis (an invocation each) */
    uint obstacleCount;
    uint cells[3];
    uint dim;
    float origin[3];
    uint periodic; /* bit a: axis a is periodic (MacGrid::periodic) */
    float spacing[3];
    uint faceStart1;  /* first normal-y face */
    int boxFirst[3];  /* the box's first cell (on the grid; along a periodic axis the box wraps) */
    uint faceStart2;  /* first normal-z face (the face total in 2D) */
    uint boxCount[9]; /* per normal axis a, positions along each axis: boxCount[3 a + b] */
    uint first; /* the dispatch's first run of faces (OBSTACLE_MISMATCH_FACES_PER_INVOCATION) */
    uint pad0;
    uint pad1;
};

struct ModalCorrectParams {
    uint n;
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifdef __cplusplus
static_assert(sizeof(ObstacleRecord) == 160 && sizeof(ObstacleMismatchParams) == 128 &&
                  sizeof(ModalCorrectParams) == 16,
              "std430 and C++ layouts agree");
} /* namespace modeflow::shaders */
#endif

#endif
