// DisplayView.glsl: where a window pixel falls in the display kernels' picture (the viewport),
// what lies outside it, and the paddle drawn over it. Include after DisplayParams.h and after
// declaring `params`; Display.glsl then completes the kernel.

// Outside the viewport: the wall colour in a frame around it, darker background beyond. The
// sides of a periodic axis (params.boundary's bits 0: x, 1: y) and those the air crosses, open
// or a wind's (bits 6 + side, MacGrid::crossableSideBits: 6 left, 7 right, 8 bottom, 9 top; the
// picture's y runs down) have no wall.
vec3 marginColour(uint x, uint y) {
    const ivec2 p = ivec2(x, y), lo = ivec2(params.viewX, params.viewY);
    const ivec2 hi = lo + ivec2(params.viewWidth, params.viewHeight);
    const ivec2 outside = max(lo - p, p - hi + 1);
    const bool besideX = outside.x > 0 && outside.y <= 0, besideY = outside.y > 0 && outside.x <= 0;
    const uint sideX = p.x < lo.x ? 6u : 7u, sideY = p.y < lo.y ? 9u : 8u;
    const bool open = (besideX && (params.boundary & (1u | (1u << sideX))) != 0u) ||
                      (besideY && (params.boundary & (2u | (1u << sideY))) != 0u);
    if (max(outside.x, outside.y) <= DISPLAY_FRAME_PIXELS && !open)
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
