// Display.glsl: what both display kernels share: the overlay, sRGB packing in the swapchain's
// byte order, and main(): each invocation writes four
// consecutive window pixels, the four of one overlay word (one load for them, and a quarter of
// the invocations: faster on lavapipe). Include after DisplayParams.h and after declaring `params`,
// the buffers `overlayWords` (one byte per pixel, 4 to a word) and `pixels` (one word per pixel),
// and `vec3 pixelColour(uint x, uint y)`: the colour of window pixel (x, y) under the overlay.

vec3 withOverlay(vec3 colour, uint code) {
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

void main() {
    const uint total = params.width * params.height;
    const uint first = 4u * gl_GlobalInvocationID.x;
    if (first >= total) return;
    const uint codes = overlayWords[gl_GlobalInvocationID.x];
    uint y = first / params.width, x = first - y * params.width;
    [[unroll]] for (uint k = 0u; k < 4u; ++k) {
        const uint pixel = first + k;
        if (pixel < total)
            pixels[pixel] = packColour(withOverlay(pixelColour(x, y), (codes >> (8u * k)) & 0xffu));
        if (++x == params.width) {
            x = 0u;
            ++y;
        }
    }
}
