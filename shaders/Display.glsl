// Display.glsl: what both display kernels share: the overlay, sRGB packing in the swapchain's
// byte order, and where a window pixel falls in the viewport. Include after DisplayParams.h and
// after declaring `params` and the buffer `overlayWords` (one byte per pixel, 4 to a word).

uint overlayAt(uint pixel) { return (overlayWords[pixel >> 2] >> ((pixel & 3u) * 8u)) & 0xffu; }

vec3 withOverlay(vec3 colour, uint pixel) {
    const uint code = overlayAt(pixel);
    if (code == DISPLAY_OVERLAY_TEXT) return vec3(0.95, 0.96, 0.98);
    if (code == DISPLAY_OVERLAY_SHADOW) return colour * 0.1;
    if (code == DISPLAY_OVERLAY_PANEL) return colour * 0.35;
    return colour;
}

uint packColour(vec3 c) {
    const uvec3 b = uvec3(round(clamp(c, 0.0, 1.0) * 255.0));
    return params.blueFirst != 0u ? (b.b | (b.g << 8) | (b.r << 16) | (255u << 24))
                                  : (b.r | (b.g << 8) | (b.b << 16) | (255u << 24));
}

// Outside the viewport: the wall colour in a frame around it, darker background beyond.
vec3 marginColour(uint x, uint y) {
    const ivec2 p = ivec2(x, y), lo = ivec2(params.viewX, params.viewY);
    const ivec2 hi = lo + ivec2(params.viewWidth, params.viewHeight);
    const ivec2 outside = max(lo - p, p - hi + 1);
    if (max(outside.x, outside.y) <= DISPLAY_FRAME_PIXELS)
        return vec3(DISPLAY_WALL_R, DISPLAY_WALL_G, DISPLAY_WALL_B);
    return DISPLAY_MARGIN * vec3(DISPLAY_BACKGROUND_R, DISPLAY_BACKGROUND_G, DISPLAY_BACKGROUND_B);
}

// The pixel's centre in source units (x right, y down, [0, sourceWidth] x [0, sourceHeight]);
// false outside the viewport.
bool sourcePoint(uint x, uint y, out vec2 p) {
    const ivec2 local = ivec2(x, y) - ivec2(params.viewX, params.viewY);
    if (local.x < 0 || local.y < 0 || local.x >= int(params.viewWidth) ||
        local.y >= int(params.viewHeight))
        return false;
    p = (vec2(local) + 0.5) / vec2(params.viewWidth, params.viewHeight) *
        vec2(params.sourceWidth, params.sourceHeight);
    return true;
}

// The paddle (a capsule) over the picture at source point p, in the source units the caller's
// p is in (display_smoke_2d: smoke cells, y up; display_picture: picture pixels, y down).
vec3 withPaddle(vec3 colour, vec2 p) {
    if (params.paddle == 0u) return colour;
    const vec2 axis = vec2(params.paddleAxisX, params.paddleAxisY);
    const vec2 d = p - vec2(params.paddleX, params.paddleY);
    const float along = dot(axis, axis) > 0.0 ? clamp(dot(d, axis) / dot(axis, axis), -1.0, 1.0) : 0.0;
    return length(d - along * axis) <= params.paddleRadius
               ? vec3(DISPLAY_PADDLE_R, DISPLAY_PADDLE_G, DISPLAY_PADDLE_B)
               : colour;
}
