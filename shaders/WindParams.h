/* WindParams.h: push constants of add_wind.comp, shared by C++ and GLSL (ASCII, no C++-only
   syntax outside the __cplusplus blocks); padded to 16 bytes. */
#ifndef MODEFLOW_SHADERS_WIND_PARAMS_H
#define MODEFLOW_SHADERS_WIND_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

struct WindParams {
    uint faceStart1; /* first normal-y face (MacGrid::faceOffset) */
    uint faceStart2; /* first normal-z face (the face total in 2D) */
    uint faceTotal;
    uint periodic; /* bit a: axis a is periodic (its faces have no wall) */
    uint cells[3];
    uint open; /* bit 2a + (0 low, 1 high): that side is open (its faces are DOFs, no wall) */
};

#ifdef __cplusplus
static_assert(sizeof(WindParams) == 32, "push constants are padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
