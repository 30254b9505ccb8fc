/* RenderVolumeParams.h: push constants and look constants of render_volume.comp, shared by C++
   (the CPU reference engine/preview/VolumeReference.cpp and the wrapper VolumeRenderer.cpp) and
   GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks, so glslang reads it too).
   Scalars only, 16-byte rows, so the std430 and C++ layouts agree; 112 bytes, below the
   128 bytes every Vulkan device offers.

   Units. Points are in cell units of the smoke grid (cell (i, j, k) spans [i, i+1) x [j, j+1) x
   [k, k+1), the box is [0, n]); ray parameters t are world lengths divided by L, the box's
   largest side, so a step of t moves the point by t * cellsPerT cells per axis and extinction
   is an optical depth per unit t. The camera (engine/preview/VolumeView.cpp) is the same for
   any resolution of the same box. */
#ifndef MODEFLOW_SHADERS_RENDER_VOLUME_PARAMS_H
#define MODEFLOW_SHADERS_RENDER_VOLUME_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* What one dispatch computes (`stage`). */
#define RENDER_VOLUME_STAGE_LIGHT 0u /* per (x, y) column: extinction, optical depth to the top */
#define RENDER_VOLUME_STAGE_IMAGE 1u /* per pixel: the ray march, one packed RGBA8 word */

/* The look, in linear light (the sRGB curve is applied at the end). Light comes straight from
   above (+z) with a warm white colour; the ambient term is a dim cool sky seen from everywhere.
   The scattered light L is exposed as 1 - exp(-EXPOSURE L) and added to the background. */
#define RENDER_VOLUME_LIGHT_R 1.25
#define RENDER_VOLUME_LIGHT_G 1.2
#define RENDER_VOLUME_LIGHT_B 1.12
#define RENDER_VOLUME_AMBIENT_R 0.05
#define RENDER_VOLUME_AMBIENT_G 0.06
#define RENDER_VOLUME_AMBIENT_B 0.08
#define RENDER_VOLUME_EXPOSURE 1.8
/* The background and outline as sRGB values in [0, 1] (Palette.h kBackground: 14, 16, 22). */
#define RENDER_VOLUME_BACKGROUND_R 0.0549
#define RENDER_VOLUME_BACKGROUND_G 0.0627
#define RENDER_VOLUME_BACKGROUND_B 0.0863
#define RENDER_VOLUME_OUTLINE_R 0.45
#define RENDER_VOLUME_OUTLINE_G 0.5
#define RENDER_VOLUME_OUTLINE_B 0.6
/* Outline opacity of the box edges in front of the volume and behind it. */
#define RENDER_VOLUME_FRONT_EDGE 0.35
#define RENDER_VOLUME_BACK_EDGE 0.6
/* Glass: light added per half a cell of ray (glassT) where the trilinear fluid mask w is between
   0 and 1, times 4 w (1 - w); a ray crossing the wall head-on gathers about one such step's
   worth, a grazing ray more, so the domain's boundary shows as a faint rim at any march step. */
#define RENDER_VOLUME_GLASS_R 0.0003
#define RENDER_VOLUME_GLASS_G 0.0004
#define RENDER_VOLUME_GLASS_B 0.0006
/* Flames glow (render_volume's flame variant): a sample adds flameScale * flame * dt of this
   colour, dimmed by the smoke in front of it as any light is. */
#define RENDER_VOLUME_FLAME_R 1.0
#define RENDER_VOLUME_FLAME_G 0.42
#define RENDER_VOLUME_FLAME_B 0.08
/* Rays stop once less than this fraction of the background still shows through. */
#define RENDER_VOLUME_MIN_TRANSMITTANCE 0.001

struct RenderVolumeParams {
    uint width; /* picture size in pixels; pixel (x, y) has y = 0 at the top */
    uint height;
    uint stage;
    uint itemCount; /* columns (light stage) or pixels (image stage): one invocation each */
    uint cellsX;    /* smoke grid cells per axis */
    uint cellsY;
    uint cellsZ;
    float densityScale; /* light stage: optical depth per unit t of density 1 */
    float eyeX;         /* camera position in cell units */
    float eyeY;
    float eyeZ;
    float stepT; /* ray march step, in t */
    float baseX; /* direction of pixel (x, y) before normalizing: base + (x+1/2) dx + (y+1/2) dy */
    float baseY; /* (world directions, unit length = 1 world unit) */
    float baseZ;
    float pixelAngle; /* width of a pixel in t per unit t of distance (outline width) */
    float dxX;
    float dxY;
    float dxZ;
    float hz; /* one cell along z in t (light stage) */
    float dyX;
    float dyY;
    float dyZ;
    uint densityStride; /* floats from one cell's density to the next (2: SmokeState's pairs) */
    float cellsPerTX;   /* cells per unit t along each axis: L / spacing */
    float cellsPerTY;
    float cellsPerTZ;
    float glassT;     /* the glass adds its colour per this much t of wall crossed (half a cell) */
    uint periodic;    /* bit a: axis a wraps (MacGrid::periodic), so sampling wraps across it */
    float flameScale; /* glow per unit t of flame 1 (the flame variant; 0 elsewhere) */
    uint padding1;
    uint padding2;
};

#ifdef __cplusplus
static_assert(sizeof(RenderVolumeParams) == 128, "push constants are scalars in 16-byte rows");
}  // namespace modeflow::shaders
#endif

#endif
