#pragma once
/// @file ContactSheet.h
/// Many frames on one picture: thumbnails of a common width in a grid, row by row, separated by
/// a thin gap, each numbered in its top left corner (DigitFont.h), so a run can be judged at a
/// glance.

#include <cstddef>
#include <span>
#include <vector>

#include "engine/preview/Image.h"

namespace modeflow::preview {

struct ContactSheetOptions {
    int thumbnailWidth = 256;  ///< every frame is resampled (area average) to this width
    int gap = 4;               ///< pixels between thumbnails and around the sheet
    bool numbers = true;       ///< draw the frame numbers
    std::vector<int> labels;   ///< the number of each frame (≥ 0); empty: 0, 1, 2, …
    int labelScale = 2;        ///< pixels per font pixel of the numbers
};

/// `columns` thumbnails per row; the rows are as tall as their tallest thumbnail (frames keep
/// their aspect ratio, height = round(h · thumbnailWidth / w)). Sheet size: columns · (w + gap)
/// + gap wide (fewer columns when there are fewer frames), rows · (row height + gap) + gap high.
/// @throw modeflow::Error when there are no frames, a frame is empty or inconsistent, columns,
///        thumbnail width or label scale are below 1, the gap is negative, or labels has the
///        wrong count or a negative entry.
Image contactSheet(std::span<const Image> frames, int columns,
                   const ContactSheetOptions& options = {});

/// Which of `count` frames a sheet of at most `most` shows: all when count ≤ most, else `most`
/// evenly spaced, the first and the last among them (indices in increasing order).
/// @throw modeflow::Error for `most` below 2.
std::vector<std::size_t> evenlySpaced(std::size_t count, std::size_t most);

/// `image` resampled to `width`, its height in proportion (at least 1): a sheet's thumbnail.
Image thumbnail(const Image& image, int width);

/// `image` resampled to `width` × `height` by area averaging (each output pixel is the mean of
/// the input area it covers), which neither aliases when shrinking nor blurs when growing.
Image resampled(const Image& image, int width, int height);

}  // namespace modeflow::preview
