#include "engine/preview/VolumeReference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/VolumeView.h"

namespace modeflow::preview {
namespace {

// Every line below mirrors a line of shaders/render_volume.comp; keep them in step.
using shaders::RenderVolumeParams;
using V3 = std::array<float, 3>;

V3 operator+(V3 a, V3 b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
V3 operator*(float s, V3 a) {
    return {s * a[0], s * a[1], s * a[2]};
}
V3 operator*(V3 a, V3 b) {
    return {a[0] * b[0], a[1] * b[1], a[2] * b[2]};
}
float mixf(float a, float b, float t) {
    return a * (1.0f - t) + b * t;
}

struct Volume {
    const RenderVolumeParams& p;
    std::vector<float> extinction;  // −1 marks a wall cell
    std::vector<float> depth;       // optical depth from the cell centre up to the box top
    std::span<const float> flame;   // empty: the variant without flame
};

void lightPass(Volume& v, std::span<const float> density, std::span<const std::uint8_t> mask) {
    const RenderVolumeParams& p = v.p;
    const std::uint32_t layer = p.cellsX * p.cellsY;
    for (std::uint32_t column = 0; column < layer; ++column) {
        float above = 0.0f;
        for (int z = int(p.cellsZ) - 1; z >= 0; --z) {
            const std::uint32_t cell = std::uint32_t(z) * layer + column;
            const bool fluid = mask[cell] != 0;
            const float d = density[cell];
            const float sigma = fluid && d > 0.0f ? d * p.densityScale : 0.0f;
            v.extinction[cell] = fluid ? sigma : -1.0f;
            v.depth[cell] = above + 0.5f * p.hz * sigma;
            above += p.hz * sigma;
        }
    }
}

struct Stencil {
    std::array<std::uint32_t, 8> cell;
    std::array<float, 8> weight;
};

Stencil stencilAt(const RenderVolumeParams& p, V3 point) {
    const std::array<int, 3> n{int(p.cellsX), int(p.cellsY), int(p.cellsZ)};
    std::array<int, 3> lo{}, hi{};
    V3 f{};
    for (int a = 0; a < 3; ++a) {
        if ((p.periodic >> a) & 1u) {
            // GLSL's mod(x, y) = x - y floor(x / y), whose result may round to y.
            const float s =
                (point[a] - 0.5f) - float(n[a]) * std::floor((point[a] - 0.5f) / float(n[a]));
            const float below = std::floor(s);
            lo[a] = std::clamp(int(below), 0, n[a]) % n[a];
            hi[a] = (lo[a] + 1) % n[a];
            f[a] = s - below;
            continue;
        }
        const float s = std::clamp(point[a] - 0.5f, 0.0f, float(n[a] - 1));
        lo[a] = std::min(int(std::floor(s)), std::max(n[a] - 2, 0));
        hi[a] = std::min(lo[a] + 1, n[a] - 1);
        f[a] = s - float(lo[a]);
    }
    Stencil st{};
    for (int k = 0; k < 8; ++k) {
        const int x = (k & 1) ? hi[0] : lo[0], y = (k & 2) ? hi[1] : lo[1],
                  z = (k & 4) ? hi[2] : lo[2];
        st.cell[k] = std::uint32_t((z * n[1] + y) * n[0] + x);
        st.weight[k] = ((k & 1) ? f[0] : 1.0f - f[0]) * ((k & 2) ? f[1] : 1.0f - f[1]) *
                       ((k & 4) ? f[2] : 1.0f - f[2]);
    }
    return st;
}

float edgeCoverage(const RenderVolumeParams& p, V3 point, float t, V3 cellsPerT) {
    const V3 n{float(p.cellsX), float(p.cellsY), float(p.cellsZ)};
    V3 d{};
    for (int a = 0; a < 3; ++a)
        d[a] = std::max(std::min(point[a], n[a] - point[a]), 0.0f) / cellsPerT[a];
    const float second = std::max(std::min(d[0], d[1]), std::min(std::max(d[0], d[1]), d[2]));
    return std::clamp(1.25f - second / (t * p.pixelAngle), 0.0f, 1.0f);
}

float encode(float linear) {
    return linear > 0.0f ? std::pow(linear, 1.0f / 2.2f) : 0.0f;
}

Rgba renderPixel(const Volume& v, std::uint32_t px, std::uint32_t py) {
    const RenderVolumeParams& p = v.p;
    V3 world = V3{p.baseX, p.baseY, p.baseZ} + (float(px) + 0.5f) * V3{p.dxX, p.dxY, p.dxZ} +
               (float(py) + 0.5f) * V3{p.dyX, p.dyY, p.dyZ};
    world =
        (1.0f / std::sqrt(world[0] * world[0] + world[1] * world[1] + world[2] * world[2])) * world;
    const V3 cellsPerT{p.cellsPerTX, p.cellsPerTY, p.cellsPerTZ};
    const V3 dir = world * cellsPerT;
    const V3 eye{p.eyeX, p.eyeY, p.eyeZ};
    const V3 n{float(p.cellsX), float(p.cellsY), float(p.cellsZ)};

    float tNear = 0.0f, tFar = 1e30f;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / (std::abs(dir[a]) < 1e-20f ? 1e-20f : dir[a]);
        const float t0 = (0.0f - eye[a]) * inv;
        const float t1 = (n[a] - eye[a]) * inv;
        tNear = std::max(tNear, std::min(t0, t1));
        tFar = std::min(tFar, std::max(t0, t1));
    }
    const V3 lightColour{RENDER_VOLUME_LIGHT_R, RENDER_VOLUME_LIGHT_G, RENDER_VOLUME_LIGHT_B};
    const V3 ambient{RENDER_VOLUME_AMBIENT_R, RENDER_VOLUME_AMBIENT_G, RENDER_VOLUME_AMBIENT_B};
    const V3 glass{RENDER_VOLUME_GLASS_R, RENDER_VOLUME_GLASS_G, RENDER_VOLUME_GLASS_B};
    const V3 flameColour{RENDER_VOLUME_FLAME_R, RENDER_VOLUME_FLAME_G, RENDER_VOLUME_FLAME_B};
    const V3 outline{RENDER_VOLUME_OUTLINE_R, RENDER_VOLUME_OUTLINE_G, RENDER_VOLUME_OUTLINE_B};
    V3 background{RENDER_VOLUME_BACKGROUND_R, RENDER_VOLUME_BACKGROUND_G,
                  RENDER_VOLUME_BACKGROUND_B};
    V3 light{0.0f, 0.0f, 0.0f};
    float transmittance = 1.0f;
    const bool hit = tNear < tFar;
    if (hit) {
        const float back =
            RENDER_VOLUME_BACK_EDGE * edgeCoverage(p, eye + tFar * dir, tFar, cellsPerT);
        for (int c = 0; c < 3; ++c) background[c] = mixf(background[c], outline[c], back);
        const int steps = std::max(1, int(std::ceil((tFar - tNear) / p.stepT)));
        const float dt = (tFar - tNear) / float(steps);
        const float glassPerStep = dt / p.glassT;
        for (int i = 0; i < steps; ++i) {
            const Stencil st = stencilAt(p, eye + (tNear + (float(i) + 0.5f) * dt) * dir);
            float sigma = 0.0f, fluid = 0.0f;
            for (int k = 0; k < 8; ++k) {
                const float e = v.extinction[st.cell[k]];
                sigma += st.weight[k] * std::max(e, 0.0f);
                fluid += st.weight[k] * (e >= 0.0f ? 1.0f : 0.0f);
            }
            light =
                light + (transmittance * (glassPerStep * 4.0f * fluid * (1.0f - fluid))) * glass;
            if (!v.flame.empty()) {
                float f = 0.0f;
                for (int k = 0; k < 8; ++k) f += st.weight[k] * v.flame[st.cell[k]];
                light = light + (transmittance * (p.flameScale * f * dt)) * flameColour;
            }
            if (sigma > 0.0f) {
                float tau = 0.0f;
                for (int k = 0; k < 8; ++k) tau += st.weight[k] * v.depth[st.cell[k]];
                const float absorbed = 1.0f - std::exp(-sigma * dt);
                light =
                    light + (transmittance * absorbed) * (std::exp(-tau) * lightColour + ambient);
                transmittance *= 1.0f - absorbed;
                if (transmittance < RENDER_VOLUME_MIN_TRANSMITTANCE) break;
            }
        }
    }
    V3 colour{};
    for (int c = 0; c < 3; ++c)
        colour[c] = encode(1.0f - std::exp(-float(RENDER_VOLUME_EXPOSURE) * light[c])) +
                    transmittance * background[c];
    if (hit) {
        const float front =
            RENDER_VOLUME_FRONT_EDGE * edgeCoverage(p, eye + tNear * dir, tNear, cellsPerT);
        for (int c = 0; c < 3; ++c) colour[c] = mixf(colour[c], outline[c], front);
    }
    Rgba out{0, 0, 0, 255};
    for (int c = 0; c < 3; ++c)
        out[c] = std::uint8_t(std::clamp(colour[c], 0.0f, 1.0f) * 255.0f + 0.5f);
    return out;
}

}  // namespace

Image renderVolumeReference(const MacGrid& grid, std::span<const float> density,
                            std::span<const std::uint8_t> mask, int width, int height,
                            float densityScale, std::span<const float> flame, float flameScale) {
    RenderVolumeParams params = volumeViewParams(grid, width, height, densityScale);
    const auto cells = std::size_t(grid.cellCount());
    if (density.size() != cells || mask.size() != cells)
        throw Error("3D preview: " + std::to_string(density.size()) + " densities and " +
                    std::to_string(mask.size()) + " mask bytes for " + std::to_string(cells) +
                    " smoke cells");
    if (!flame.empty() && flame.size() != cells)
        throw Error("3D preview: " + std::to_string(flame.size()) + " flame values for " +
                    std::to_string(cells) + " smoke cells");
    params.flameScale = flame.empty() ? 0.0f : checkedFlameScale(flameScale);
    Volume volume{params, std::vector<float>(cells), std::vector<float>(cells), flame};
    lightPass(volume, density, mask);
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.setPixel(x, y, renderPixel(volume, std::uint32_t(x), std::uint32_t(y)));
    return image;
}

}  // namespace modeflow::preview
