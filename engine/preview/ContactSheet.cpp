#include "engine/preview/ContactSheet.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/preview/DigitFont.h"
#include "engine/preview/Palette.h"

namespace modeflow::preview {
namespace {

/// For output pixel i of n over an input of m pixels: the input pixels it covers and how much.
struct Footprint {
    int first;
    int last;  // inclusive
    double begin;
    double end;  // in input pixels
};

Footprint footprint(int i, int n, int m) {
    const double scale = double(m) / double(n);
    const double begin = i * scale, end = (i + 1) * scale;
    return {int(std::floor(begin)), std::min(int(std::ceil(end)) - 1, m - 1), begin, end};
}

double overlap(const Footprint& f, int pixel) {
    return std::min(f.end, double(pixel + 1)) - std::max(f.begin, double(pixel));
}

void checkFrame(const Image& frame, std::size_t index) {
    if (frame.width < 1 || frame.height < 1 ||
        frame.rgba.size() != std::size_t(frame.width) * std::size_t(frame.height) * 4)
        throw Error("contact sheet: frame " + std::to_string(index) + " is empty or its " +
                    std::to_string(frame.rgba.size()) + " bytes do not match " +
                    std::to_string(frame.width) + " × " + std::to_string(frame.height) + " pixels");
}

}  // namespace

Image resampled(const Image& image, int width, int height) {
    Image out(width, height);
    for (int y = 0; y < height; ++y) {
        const Footprint fy = footprint(y, height, image.height);
        for (int x = 0; x < width; ++x) {
            const Footprint fx = footprint(x, width, image.width);
            double sum[4] = {0, 0, 0, 0}, weight = 0.0;
            for (int sy = fy.first; sy <= fy.last; ++sy)
                for (int sx = fx.first; sx <= fx.last; ++sx) {
                    const double w = overlap(fy, sy) * overlap(fx, sx);
                    const std::size_t o = image.offset(sx, sy);
                    for (int c = 0; c < 4; ++c) sum[c] += w * image.rgba[o + c];
                    weight += w;
                }
            Rgba c{};
            for (int k = 0; k < 4; ++k) c[k] = std::uint8_t(std::lround(sum[k] / weight));
            out.setPixel(x, y, c);
        }
    }
    return out;
}

std::vector<std::size_t> evenlySpaced(std::size_t count, std::size_t most) {
    if (most < 2)
        throw Error("contact sheet: at most " + std::to_string(most) + " frames (at least 2)");
    std::vector<std::size_t> chosen;
    if (count <= most) {
        for (std::size_t i = 0; i < count; ++i) chosen.push_back(i);
        return chosen;
    }
    // Index i·(count − 1)/(most − 1), rounded: distinct, as the step is above 1.
    for (std::size_t i = 0; i < most; ++i)
        chosen.push_back((i * (count - 1) + (most - 1) / 2) / (most - 1));
    return chosen;
}

Image thumbnail(const Image& image, int width) {
    const int height = std::max(1, int(std::lround(double(image.height) * width / image.width)));
    return resampled(image, width, height);
}

Image contactSheet(std::span<const Image> frames, int columns, const ContactSheetOptions& o) {
    const auto fail = [](const std::string& why) { return Error("contact sheet: " + why); };
    if (frames.empty()) throw fail("no frames");
    if (columns < 1) throw fail(std::to_string(columns) + " columns (at least 1)");
    if (o.thumbnailWidth < 1)
        throw fail("thumbnail width " + std::to_string(o.thumbnailWidth) + " < 1");
    if (o.gap < 0) throw fail("gap " + std::to_string(o.gap) + " < 0");
    if (o.labelScale < 1) throw fail("label scale " + std::to_string(o.labelScale) + " < 1");
    if (!o.labels.empty() && o.labels.size() != frames.size())
        throw fail(std::to_string(o.labels.size()) + " labels for " +
                   std::to_string(frames.size()) + " frames");
    for (int label : o.labels)
        if (label < 0) throw fail("frame number " + std::to_string(label) + " is negative");

    std::vector<Image> thumbs;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        checkFrame(frames[f], f);
        thumbs.push_back(thumbnail(frames[f], o.thumbnailWidth));
    }
    const int used = std::min<int>(columns, int(frames.size()));
    const int rows = (int(frames.size()) + used - 1) / used;
    std::vector<int> rowHeight(std::size_t(rows), 0), rowTop(std::size_t(rows) + 1, o.gap);
    for (std::size_t f = 0; f < thumbs.size(); ++f)
        rowHeight[f / used] = std::max(rowHeight[f / used], thumbs[f].height);
    for (int r = 0; r < rows; ++r) rowTop[r + 1] = rowTop[r] + rowHeight[r] + o.gap;

    Image sheet(used * (o.thumbnailWidth + o.gap) + o.gap, rowTop[rows], palette::kSheetBackground);
    for (std::size_t f = 0; f < thumbs.size(); ++f) {
        const int left = o.gap + int(f % used) * (o.thumbnailWidth + o.gap), top = rowTop[f / used];
        for (int y = 0; y < thumbs[f].height; ++y)
            std::copy_n(thumbs[f].rgba.begin() + std::ptrdiff_t(thumbs[f].offset(0, y)),
                        4 * thumbs[f].width,
                        sheet.rgba.begin() + std::ptrdiff_t(sheet.offset(left, top + y)));
        if (o.numbers)
            drawNumber(sheet, left + o.labelScale, top + o.labelScale,
                       o.labels.empty() ? int(f) : o.labels[f], o.labelScale, palette::kLabel);
    }
    return sheet;
}

}  // namespace modeflow::preview
