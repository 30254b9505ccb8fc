/* DisplayParams.h: push constants and look of the stir window's display kernels
   (display_smoke_2d.comp, display_picture.comp; wrapper engine/display/DisplayKernels.cpp),
   shared by C++ and GLSL (ASCII, no C++-only syntax outside the __cplusplus blocks, so glslang
   reads it too). Scalars only, 16-byte rows, so the std430 and C++ layouts agree.

   Both kernels write one packed 8-bit colour per window pixel (rows from the top) in the byte
   order of the swapchain's format, ready for vkCmdCopyBufferToImage: the picture fills the
   viewport (letterboxed: it keeps its aspect ratio), the rest is background, and the text
   overlay is drawn on top. */
#ifndef MODEFLOW_SHADERS_DISPLAY_PARAMS_H
#define MODEFLOW_SHADERS_DISPLAY_PARAMS_H

#ifdef __cplusplus
#include <cstdint>
namespace modeflow::shaders {
using uint = std::uint32_t;
#endif

/* Overlay codes, one byte per window pixel (TextOverlay.h). */
#define DISPLAY_OVERLAY_NONE 0u
#define DISPLAY_OVERLAY_PANEL 1u  /* darkened: the panel behind text */
#define DISPLAY_OVERLAY_SHADOW 2u /* the glyph's shadow, nearly black */
#define DISPLAY_OVERLAY_TEXT 3u   /* the glyph */

/* 2D smoke colours: sRGB in [0, 1], those of the PNG previews (engine/preview/Palette.h). The
   density d is toned as (1 - exp(-TONE d / scale)) / (1 - exp(-TONE)), clamped to 1. */
#define DISPLAY_BACKGROUND_R 0.0549
#define DISPLAY_BACKGROUND_G 0.0627
#define DISPLAY_BACKGROUND_B 0.0863
#define DISPLAY_WALL_R 0.251
#define DISPLAY_WALL_G 0.2745
#define DISPLAY_WALL_B 0.3373
#define DISPLAY_SMOKE_R 0.9255
#define DISPLAY_SMOKE_G 0.9412
#define DISPLAY_SMOKE_B 0.9804
#define DISPLAY_HOT_R 1.0
#define DISPLAY_HOT_G 0.6588
#define DISPLAY_HOT_B 0.3294
/* Where fuel burns (Palette.h kFlame: 255, 196, 64). */
#define DISPLAY_FLAME_R 1.0
#define DISPLAY_FLAME_G 0.7686
#define DISPLAY_FLAME_B 0.2510
#define DISPLAY_TONE 2.5
/* Outside the viewport, a shade darker than the background, with a frame of the wall colour
   this many pixels wide around the picture (the box's walls; not on the sides of a periodic
   axis or those a wind flows through, which have none). */
#define DISPLAY_MARGIN 0.6
#define DISPLAY_FRAME_PIXELS 3
/* Velocity arrows. */
#define DISPLAY_ARROW_R 0.45
#define DISPLAY_ARROW_G 0.75
#define DISPLAY_ARROW_B 1.0
/* The paddle. */
#define DISPLAY_PADDLE_R 0.85
#define DISPLAY_PADDLE_G 0.35
#define DISPLAY_PADDLE_B 0.3

struct DisplayParams {
    uint width; /* window pixels: the output buffer is width * height words */
    uint height;
    uint viewX; /* the viewport the picture fills, in window pixels */
    uint viewY;
    uint viewWidth;
    uint viewHeight;
    uint sourceWidth; /* the picture (display_picture) or the smoke grid (display_smoke_2d) */
    uint sourceHeight;
    uint blueFirst;     /* 1: the swapchain format stores blue in the low byte (B8G8R8A8) */
    float densityScale; /* 2D: the density shown fully bright */
    float hotScale;     /* 2D: the temperature shown fully hot (0: no tint) */
    uint paddle;        /* 1 draws the paddle, a capsule, in source units (display_smoke_2d: */
    float paddleX;      /* smoke cells, y up; display_picture: picture pixels, y down): */
    float paddleY;      /* its centre, */
    float paddleAxisX;  /* from the centre to one end of its segment, */
    float paddleAxisY;
    float paddleRadius; /* and its radius */
    uint arrows;        /* display_smoke_2d: 1 draws velocity arrows, one per square of */
    float arrowSpacing; /* this many window pixels, */
    float arrowScale;   /* window pixels per unit of velocity, */
    uint basisX;        /* from the face velocity of the basis grid of basisX x basisY cells */
    uint basisY;
    uint boundary;    /* display_smoke_2d: MacGrid::boundaryBits: bit a, axis a is periodic (the
                         smoke and velocity wrap); bit 3 + a, the air crosses a side across it
                         (the velocity is sampled there as in the air); and bit 6 + side,
                         MacGrid::crossableSideBits: that side (open or a wind's) has no wall
                         frame, nor have a periodic axis's */
    float flameScale; /* display_smoke_2d: the flame shown fully glowing (0: no flame) */
};

/* display_dots.comp: particles as dots over the finished picture. */
struct DisplayDotsParams {
    uint count; /* dots: one (x, y) in window pixels each, y down */
    uint width; /* window pixels */
    uint height;
    uint colour; /* the packed pixel, in the screen's byte order */
};

#ifdef __cplusplus
static_assert(sizeof(DisplayParams) == 96 && sizeof(DisplayDotsParams) == 16,
              "push constants are scalars in 16-byte rows");
}  // namespace modeflow::shaders
#endif

#endif
