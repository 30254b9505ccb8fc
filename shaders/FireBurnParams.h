/* FireBurnParams.h: push constants of fire_burn.comp (fuel burning, engine/device/FireBurn.h),
   shared by C++ and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks); scalars
   padded to 16 bytes, so the std430 and C++ layouts agree. */
#ifndef MODEFLOW_SHADERS_FIRE_BURN_PARAMS_H
#define MODEFLOW_SHADERS_FIRE_BURN_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

struct FireBurnParams {
    uint cellCount; /* smoke cells */
    uint firstCell; /* this dispatch handles cells firstCell ... firstCell + invocations - 1 */
    float ignition;
    float burnFraction; /* 1 - exp(-burn_rate dt), from the host in double precision */
    float heat;
    float smoke;
    float inverseDt;
    float pad0;
};

#ifdef __cplusplus
static_assert(sizeof(FireBurnParams) == 32, "push constants are scalars padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
