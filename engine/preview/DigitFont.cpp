#include "engine/preview/DigitFont.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

namespace modeflow::preview {
namespace {

// Rows top to bottom, 3 bits each (bit 2 is the left column).
constexpr std::array<std::array<std::uint8_t, 5>, 10> kDigits{{
    {7, 5, 5, 5, 7},  // 0
    {2, 6, 2, 2, 7},  // 1
    {7, 1, 7, 4, 7},  // 2
    {7, 1, 3, 1, 7},  // 3
    {5, 5, 7, 1, 1},  // 4
    {7, 4, 7, 1, 7},  // 5
    {7, 4, 7, 5, 7},  // 6
    {7, 1, 2, 2, 2},  // 7
    {7, 5, 7, 5, 7},  // 8
    {7, 5, 7, 1, 7},  // 9
}};
constexpr int kMargin = 1;  // font pixels of box around the digits, and between digits
constexpr Rgba kBox{0, 0, 0, 255};

void fill(Image& image, int x0, int y0, int w, int h, Rgba colour, float opacity) {
    for (int y = std::max(y0, 0); y < std::min(y0 + h, image.height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x0 + w, image.width); ++x) {
            Rgba c = image.pixel(x, y);
            for (int k = 0; k < 3; ++k)
                c[k] =
                    std::uint8_t(float(c[k]) + (float(colour[k]) - float(c[k])) * opacity + 0.5f);
            image.setPixel(x, y, c);
        }
}

}  // namespace

int numberWidth(int number, int scale) {
    const int digits = int(std::to_string(number).size());
    return (digits * 4 - 1 + 2 * kMargin) * scale;
}

int numberHeight(int scale) {
    return (5 + 2 * kMargin) * scale;
}

void drawNumber(Image& image, int x, int y, int number, int scale, Rgba colour) {
    // A translucent box keeps some of the picture visible behind the label.
    fill(image, x, y, numberWidth(number, scale), numberHeight(scale), kBox, 0.6f);
    const std::string text = std::to_string(number);
    for (std::size_t d = 0; d < text.size(); ++d) {
        const auto& glyph = kDigits[std::size_t(text[d] - '0')];
        const int left = x + (kMargin + 4 * int(d)) * scale;
        for (int row = 0; row < 5; ++row)
            for (int column = 0; column < 3; ++column)
                if (glyph[row] & (4 >> column))
                    fill(image, left + column * scale, y + (kMargin + row) * scale, scale, scale,
                         colour, 1.0f);
    }
}

}  // namespace modeflow::preview
