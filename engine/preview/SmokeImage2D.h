#pragma once
/// @file SmokeImage2D.h
/// A picture of a 2D scene's smoke, drawn on the CPU (a 2D grid is small): one block of whole
/// pixels per smoke cell (square for square cells), y up (the grid's top row is the picture's top
/// row), a dark background, smoke white-ish with density through a tone curve, tinted warm where it
/// is hot, glowing flame-coloured where fuel burns (over the smoke, as a flame's light outshines
/// it), and cells outside the domain in the wall colour so that Ω's boundary shows (palette in
/// Palette.h).
///
/// Brightness: density d maps to b = (1 − e^{−k d/s}) / (1 − e^{−k}) with k = 2.5, clamped to 1,
/// so d = s is full white and thin smoke stays visible. The exposure s is `densityScale` when
/// given, else the `exposurePercentile` of the positive fluid densities (a few hot cells do not
/// darken the rest; a frame without smoke uses s = 1).

#include <optional>
#include <span>

#include "engine/core/MacGrid.h"
#include "engine/preview/Image.h"

namespace modeflow::preview {

struct Smoke2DOptions {
    int targetWidth = 512;               ///< pixels per cell = max(1, round(targetWidth / cells x))
    std::optional<double> densityScale;  ///< fixed exposure s (> 0); empty: automatic
    double exposurePercentile = 0.99;    ///< automatic exposure: this quantile, in (0, 1]
    std::optional<double> temperatureScale;  ///< temperature of full tint (> 0); empty: the max
    double tint = 0.8;                       ///< strength of the warm tint in [0, 1]; 0: none
    /// Flame (fuel burned per unit time) of full glow (> 0); empty: the largest flame.
    std::optional<double> flameScale;
};

/// `density`, `temperature` (empty: no tint) and `flame` (empty: no glow) hold one value per cell
/// of the 2D `smokeGrid` (MacGrid::cellIndex order), `fluidMask` one byte per cell, non-zero
/// inside Ω (empty: all fluid). Non-finite values count as 0. A cell glows as
/// mix(smoke colour, flame colour, min(1, flame / flameScale)).
/// @throw modeflow::Error when the grid is not 2D, a span has the wrong size, or an option is
///        out of range.
Image renderSmoke2D(const MacGrid& smokeGrid, std::span<const float> density,
                    std::span<const float> temperature, std::span<const float> flame,
                    std::span<const std::uint8_t> fluidMask, const Smoke2DOptions& options = {});
Image renderSmoke2D(const MacGrid& smokeGrid, std::span<const double> density,
                    std::span<const double> temperature, std::span<const double> flame,
                    std::span<const std::uint8_t> fluidMask, const Smoke2DOptions& options = {});

/// Pixels per cell that renderSmoke2D uses for a grid `cellsX` cells wide.
int pixelsPerCell(int cellsX, int targetWidth);

}  // namespace modeflow::preview
