/* SmokeDisplaceParams.h: push constants of smoke_displace.comp (smoke pushed out of solids;
   engine/device/SmokeDisplacement.h), shared by C++ and GLSL (ASCII, no C++-only syntax outside
   the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_SMOKE_DISPLACE_PARAMS_H
#define MODEFLOW_SHADERS_SMOKE_DISPLACE_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* The stages of a substep, the kernel's specialization constant 1. */
#define SMOKE_DISPLACE_COVER 0u  /* which solid covers each fluid cell of the box; list them */
#define SMOKE_DISPLACE_PUSH 1u   /* covered cells: where their smoke goes, stashed, then 0 */
#define SMOKE_DISPLACE_GATHER 2u /* receiving cells: what their covered neighbours push to them */
#define SMOKE_DISPLACE_ARGS 3u   /* the lists' stages' indirect dispatch arguments */
#define SMOKE_DISPLACE_STASH                                           \
    4u /* covered cells: a second pair's values stashed, then 0, to go \
          where the push sent the first pair's (its target words) */
/* A target word's low byte when a covered cell has no free neighbour: its smoke is removed. */
#define SMOKE_DISPLACE_NOWHERE 255u
/* A free cell's target word's low byte once it is listed to receive smoke in the substep. */
#define SMOKE_DISPLACE_RECEIVES 254u

struct SmokeDisplaceParams {
    int boxFirst[3]; /* the box's first cell; wraps along periodic axes */
    uint boxLines;   /* its lines of cells along x: the cover's invocations */
    uint boxCount[3];
    uint dim;
    uint cells[3]; /* the smoke grid */
    uint periodic; /* bit a: axis a is periodic */
    float origin[3];
    uint stamp; /* this substep's number (< 2^24), in the high bits of the cover and target words */
    float spacing[3];
    uint firstRecord; /* this substep's first obstacle record */
    uint obstacleCount;
    float dt;
    uint firstInvocation; /* of this dispatch (the cover's: its first line), when a box needs
                             several */
    uint maxGroups;       /* the device's maxComputeWorkGroupCount[0] */
};

#ifdef __cplusplus
static_assert(sizeof(SmokeDisplaceParams) == 96, "std430 and C++ layouts agree");
} /* namespace modeflow::shaders */
#endif

#endif
