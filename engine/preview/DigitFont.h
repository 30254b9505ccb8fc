#pragma once
/// @file DigitFont.h
/// A built-in 3 × 5 pixel digit font, enough to number frames on a contact sheet without a font
/// library. Each font pixel is drawn as a `scale` × `scale` block over a dark box, so the
/// number reads on bright smoke and dark background alike.

#include "engine/preview/Image.h"

namespace modeflow::preview {

/// Size in pixels of `number` (≥ 0) drawn by drawNumber with `scale`, box margin included.
int numberWidth(int number, int scale);
int numberHeight(int scale);

/// Draws the decimal digits of `number` (≥ 0) with their box's top left corner at (x, y),
/// clipped to the image.
void drawNumber(Image& image, int x, int y, int number, int scale, Rgba colour);

}  // namespace modeflow::preview
