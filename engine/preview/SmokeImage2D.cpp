#include "engine/preview/SmokeImage2D.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/Palette.h"

namespace modeflow::preview {
namespace {

constexpr double kToneSteepness = 2.5;

template <typename T>
double finiteOrZero(T v) {
    return std::isfinite(v) ? double(v) : 0.0;
}

void checkInputs(const MacGrid& grid, std::size_t density, std::size_t temperature,
                 std::size_t flame, std::size_t mask, const Smoke2DOptions& o) {
    const auto fail = [](const std::string& why) { return Error("2D preview: " + why); };
    if (grid.dim != 2)
        throw fail("the smoke grid is " + std::to_string(grid.dim) + "D, expected 2D");
    const std::size_t cells = std::size_t(grid.cellCount());
    const auto checkSize = [&](const char* what, std::size_t n, bool mayBeEmpty) {
        if (n != cells && !(mayBeEmpty && n == 0))
            throw fail(std::string(what) + " has " + std::to_string(n) + " values for " +
                       std::to_string(cells) + " smoke cells");
    };
    checkSize("density", density, false);
    checkSize("temperature", temperature, true);
    checkSize("flame", flame, true);
    checkSize("fluid mask", mask, true);
    if (o.targetWidth < 1) throw fail("target width " + std::to_string(o.targetWidth) + " < 1");
    if (o.densityScale && !(*o.densityScale > 0.0 && std::isfinite(*o.densityScale)))
        throw fail("density scale " + std::to_string(*o.densityScale) + " is not positive");
    if (!(o.exposurePercentile > 0.0 && o.exposurePercentile <= 1.0))
        throw fail("exposure percentile " + std::to_string(o.exposurePercentile) +
                   " is outside (0, 1]");
    if (o.temperatureScale && !(*o.temperatureScale > 0.0 && std::isfinite(*o.temperatureScale)))
        throw fail("temperature scale " + std::to_string(*o.temperatureScale) + " is not positive");
    if (o.flameScale && !(*o.flameScale > 0.0 && std::isfinite(*o.flameScale)))
        throw fail("flame scale " + std::to_string(*o.flameScale) + " is not positive");
    if (!(o.tint >= 0.0 && o.tint <= 1.0))
        throw fail("tint " + std::to_string(o.tint) + " is outside [0, 1]");
}

/// The quantile `q` of the positive values among fluid cells; `fallback` when there are none.
template <typename T>
double positiveQuantile(std::span<const T> values, std::span<const std::uint8_t> mask, double q,
                        double fallback) {
    std::vector<double> positive;
    for (std::size_t c = 0; c < values.size(); ++c) {
        const double v = finiteOrZero(values[c]);
        if (v > 0.0 && (mask.empty() || mask[c] != 0)) positive.push_back(v);
    }
    if (positive.empty()) return fallback;
    const auto k = std::size_t(std::floor(q * double(positive.size() - 1)));
    std::nth_element(positive.begin(), positive.begin() + std::ptrdiff_t(k), positive.end());
    return positive[k];
}

std::uint8_t mixByte(std::uint8_t a, std::uint8_t b, double t) {
    return std::uint8_t(std::lround(double(a) + (double(b) - double(a)) * t));
}

/// `given`, else the largest value of `values` in the fluid (0 with none).
template <typename T>
double scaleOf(const std::optional<double>& given, std::span<const T> values,
               std::span<const std::uint8_t> mask) {
    if (given) return *given;
    double most = 0.0;
    for (std::size_t c = 0; c < values.size(); ++c)
        if (mask.empty() || mask[c] != 0) most = std::max(most, finiteOrZero(values[c]));
    return most;
}

/// values[c] / scale in [0, 1]; 0 without values.
template <typename T>
double fractionOf(std::span<const T> values, std::size_t c, double scale) {
    return values.empty() || scale <= 0.0 ? 0.0
                                          : std::clamp(finiteOrZero(values[c]) / scale, 0.0, 1.0);
}

template <typename T>
Image render(const MacGrid& grid, std::span<const T> density, std::span<const T> temperature,
             std::span<const T> flame, std::span<const std::uint8_t> mask,
             const Smoke2DOptions& o) {
    checkInputs(grid, density.size(), temperature.size(), flame.size(), mask.size(), o);
    const double scale = o.densityScale
                             ? *o.densityScale
                             : positiveQuantile(density, mask, o.exposurePercentile, 1.0);
    const double hot = scaleOf(o.temperatureScale, temperature, mask);
    const double burning = scaleOf(o.flameScale, flame, mask);
    const double toneNorm = 1.0 - std::exp(-kToneSteepness);

    const int nx = grid.cells[0], ny = grid.cells[1];
    const int p = pixelsPerCell(nx, o.targetWidth);
    // Cells that are not square keep their shape, rounded to whole pixels.
    const int q = std::max(1, int(std::lround(p * grid.spacing[1] / grid.spacing[0])));
    Image image(nx * p, ny * q, palette::kBackground);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const auto c = std::size_t(grid.cellIndex(x, y, 0));
            Rgba colour = palette::kWall;
            if (mask.empty() || mask[c] != 0) {
                const double d = std::max(0.0, finiteOrZero(density[c]));
                const double b =
                    std::min(1.0, (1.0 - std::exp(-kToneSteepness * d / scale)) / toneNorm);
                const double heat = fractionOf(temperature, c, hot);
                const double glow = fractionOf(flame, c, burning);
                for (int k = 0; k < 3; ++k) {
                    const std::uint8_t smoke =
                        mixByte(palette::kSmoke[k], palette::kHotSmoke[k], o.tint * heat);
                    colour[k] = mixByte(mixByte(palette::kBackground[k], smoke, b),
                                        palette::kFlame[k], glow);
                }
            }
            // y up: grid row y is picture row ny − 1 − y.
            const int top = (ny - 1 - y) * q;
            for (int py = top; py < top + q; ++py)
                for (int px = x * p; px < (x + 1) * p; ++px) image.setPixel(px, py, colour);
        }
    return image;
}

}  // namespace

int pixelsPerCell(int cellsX, int targetWidth) {
    return std::max(1, int(std::lround(double(targetWidth) / double(std::max(cellsX, 1)))));
}

Image renderSmoke2D(const MacGrid& grid, std::span<const float> density,
                    std::span<const float> temperature, std::span<const float> flame,
                    std::span<const std::uint8_t> mask, const Smoke2DOptions& options) {
    return render(grid, density, temperature, flame, mask, options);
}

Image renderSmoke2D(const MacGrid& grid, std::span<const double> density,
                    std::span<const double> temperature, std::span<const double> flame,
                    std::span<const std::uint8_t> mask, const Smoke2DOptions& options) {
    return render(grid, density, temperature, flame, mask, options);
}

}  // namespace modeflow::preview
