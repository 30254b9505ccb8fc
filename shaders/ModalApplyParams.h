/* ModalApplyParams.h: push constants of modal_apply.comp, shared by C++ and GLSL (kept ASCII and
   free of C++-only syntax outside the __cplusplus blocks, so glslang reads it too). Padded to 16
   bytes so the std430 push-constant layout and the C++ layout agree. */
#ifndef MODEFLOW_SHADERS_MODAL_APPLY_PARAMS_H
#define MODEFLOW_SHADERS_MODAL_APPLY_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

struct ModalApplyParams {
    uint n;          /* number of modes N; one workgroup per output k < N */
    uint pairCount;  /* N(N-1)/2 stored pairs k < j (engine/dynamics/PackedLayout.h) */
    uint pad0;
    uint pad1;
};

#ifdef __cplusplus
static_assert(sizeof(ModalApplyParams) == 16, "push constants are padded to 16 bytes");
}  // namespace modeflow::shaders
#endif

#endif
