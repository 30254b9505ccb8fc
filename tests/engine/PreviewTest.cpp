/// @file PreviewTest.cpp
/// engine/preview: PNG files read back by stb_image; 2D pictures (bright where the smoke is,
/// walls outside Ω, y up, warm tint); the 3D device renderer against its CPU reference pixel by
/// pixel, and what a viewer expects of it (height, empty volume, light from above); contact
/// sheets. Writes preview_2d.png and preview_3d.png into the test artifact folder
/// (tests/support/TestFolder.h) as samples to look at.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/preview/ContactSheet.h"
#include "engine/preview/Palette.h"
#include "engine/preview/ParticleDots.h"
#include "engine/preview/PngReader.h"
#include "engine/preview/PngWriter.h"
#include "engine/preview/SmokeImage2D.h"
#include "engine/preview/VolumeReference.h"
#include "engine/preview/VolumeRenderer.h"
#include "engine/preview/VolumeView.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/PngFile.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/TestFolder.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;
using preview::Image;
using preview::Rgba;
using testing::ballMask;
namespace palette = preview::palette;

/// [−1, 1]^dim, `n` cells per axis (a 3D grid may be stretched along z by `zScale`).
MacGrid grid(int dim, int n, int nz = 0, double zScale = 1.0) {
    MacGrid g;
    g.dim = dim;
    for (int a = 0; a < dim; ++a) {
        g.cells[a] = n;
        g.origin[a] = -1.0;
        g.spacing[a] = 2.0 / n;
    }
    if (dim == 3 && nz > 0) {
        g.cells[2] = nz;
        g.origin[2] = -zScale;
        g.spacing[2] = 2.0 * zScale / nz;
    }
    return g;
}

double centre(const MacGrid& g, int axis, int i) {
    return axis < g.dim ? g.cellCentre(axis, i) : 0.0;
}

/// One value per cell: f(x, y, z) at the cell centres.
template <typename F>
std::vector<float> cellField(const MacGrid& g, F f) {
    std::vector<float> v(std::size_t(g.cellCount()));
    for (int z = 0; z < g.cells[2]; ++z)
        for (int y = 0; y < g.cells[1]; ++y)
            for (int x = 0; x < g.cells[0]; ++x)
                v[std::size_t(g.cellIndex(x, y, z))] =
                    float(f(centre(g, 0, x), centre(g, 1, y), centre(g, 2, z)));
    return v;
}

std::vector<float> blob(const MacGrid& g, double cx, double cy, double cz, double radius,
                        double amplitude = 1.0) {
    return cellField(g, [&](double x, double y, double z) {
        const double r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz);
        return amplitude * std::exp(-r2 / (radius * radius));
    });
}

int brightness(Rgba c) {
    return (c[0] + c[1] + c[2]) / 3;
}

/// Row of the brightness-weighted centre of what differs from the picture at `empty`.
double brightRowCentre(const Image& image, const Image& empty) {
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double w =
                std::max(0, brightness(image.pixel(x, y)) - brightness(empty.pixel(x, y)));
            sum += w * y;
            weight += w;
        }
    return weight > 0.0 ? sum / weight : -1.0;
}

struct PixelDifference {
    int maxAbs = 0;        ///< largest channel difference
    double overTwo = 0.0;  ///< fraction of pixels with a channel differing by more than 2
};

PixelDifference compare(const Image& a, const Image& b) {
    PixelDifference d;
    std::size_t over = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
        int worst = 0;
        for (int c = 0; c < 4; ++c)
            worst = std::max(worst, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
        d.maxAbs = std::max(d.maxAbs, worst);
        over += worst > 2;
    }
    d.overTwo = double(over) / double(a.rgba.size() / 4);
    return d;
}

// ---------------------------------------------------------------------------------------- PNG

TEST(PngWriterTest, RoundTripKeepsSizeAndEveryPixel) {
    Image image(37, 23);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.setPixel(x, y,
                           {std::uint8_t(7 * x), std::uint8_t(11 * y), std::uint8_t(x * y),
                            std::uint8_t(255 - x)});
    const testing::TestFolder folder;
    const fs::path file = folder / "round trip.png";
    preview::writePng(file, image);

    const std::optional<testing::PngPixels> png = testing::readPng(file);
    ASSERT_TRUE(png) << file;
    EXPECT_EQ(png->width, 37);
    EXPECT_EQ(png->height, 23);
    EXPECT_EQ(png->channelsInFile, 4);
    EXPECT_TRUE(std::equal(image.rgba.begin(), image.rgba.end(), png->rgba.begin()));
    EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1)
        << "temporary file left";
}

TEST(PngWriterTest, FailuresNameTheFileAndLeaveNothingBehind) {
    const testing::TestFolder folder;
    const fs::path missing = folder / "no such folder" / "frame.png";
    try {
        preview::writePng(missing, Image(4, 4));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    Image broken(4, 4);
    broken.rgba.pop_back();
    EXPECT_THROW(preview::writePng(folder / "broken.png", broken), Error);
    EXPECT_THROW(preview::writePng(folder / "empty.png", Image()), Error);
    EXPECT_TRUE(fs::is_empty(folder));
}

// ----------------------------------------------------------------------------------------- 2D

struct Disk2D {
    MacGrid g = grid(2, 64);
    std::vector<std::uint8_t> mask = ballMask(g, 0.9);
    std::vector<float> density = blob(g, 0.1, 0.45, 0.0, 0.2);  // in the top half
    int p = preview::pixelsPerCell(64, 512);
    /// The picture's pixel at the centre of the cell that holds (x, y).
    Rgba at(const Image& image, double x, double y) const {
        const int cx = int((x + 1.0) / g.spacing[0]), cy = int((y + 1.0) / g.spacing[1]);
        return image.pixel(cx * p + p / 2, (g.cells[1] - 1 - cy) * p + p / 2);
    }
};

TEST(SmokeImage2DTest, BrightBlobDarkFluidWallsOutsideAndYUp) {
    const Disk2D s;
    const Image image = preview::renderSmoke2D(s.g, s.density, {}, {}, s.mask);
    EXPECT_EQ(s.p, 8);
    EXPECT_EQ(image.width, 512);
    EXPECT_EQ(image.height, 512);
    EXPECT_GT(brightness(s.at(image, 0.1, 0.45)), 220);       // the blob's centre: near white
    EXPECT_EQ(s.at(image, 0.0, -0.6), palette::kBackground);  // fluid without smoke
    EXPECT_EQ(s.at(image, -0.95, -0.95), palette::kWall);     // outside the disk
    EXPECT_EQ(s.at(image, 0.95, 0.95), palette::kWall);
    EXPECT_EQ(image.pixel(0, 0), palette::kWall);
    // y up: the blob at y = 0.45 is in the top half, at row (1 − 0.45) / 2 of the height.
    const double row = brightRowCentre(
        image,
        preview::renderSmoke2D(s.g, std::vector<float>(s.density.size(), 0.0f), {}, {}, s.mask));
    EXPECT_NEAR(row / image.height, (1.0 - 0.45) / 2.0, 0.02);
    preview::writePng(
        testing::artifactFolder() / "preview_2d.png",
        preview::renderSmoke2D(s.g, s.density, blob(s.g, 0.2, 0.5, 0.0, 0.12, 2.0), {}, s.mask));
}

TEST(SmokeImage2DTest, TemperatureTintsWarmAndFixedScaleSetsExposure) {
    const Disk2D s;
    const std::vector<float> hot(s.density.size(), 1.0f);
    const Rgba plain = s.at(preview::renderSmoke2D(s.g, s.density, {}, {}, s.mask), 0.1, 0.45);
    const Rgba warm = s.at(preview::renderSmoke2D(s.g, s.density, hot, {}, s.mask), 0.1, 0.45);
    EXPECT_LE(plain[0], plain[2]);               // white-blue
    EXPECT_GT(int(warm[0]) - int(warm[2]), 80);  // orange
    preview::Smoke2DOptions dim;
    dim.densityScale = 10.0;  // the blob's peak is 1: a tenth of full exposure
    const Rgba faint = s.at(preview::renderSmoke2D(s.g, s.density, {}, {}, s.mask, dim), 0.1, 0.45);
    EXPECT_LT(brightness(faint), brightness(plain) / 2);
    EXPECT_GT(brightness(faint), brightness(palette::kBackground));
    // Doubles give the same picture as floats.
    const std::vector<double> asDouble(s.density.begin(), s.density.end());
    EXPECT_EQ(preview::renderSmoke2D(s.g, asDouble, {}, {}, s.mask).rgba,
              preview::renderSmoke2D(s.g, s.density, {}, {}, s.mask).rgba);
}

TEST(SmokeImage2DTest, FlameGlowsOverTheSmokeInProportion) {
    const Disk2D s;
    std::vector<float> flame(s.density.size(), 0.0f);
    const auto cellOf = [&](double x, double y) {
        return std::size_t(
            s.g.cellIndex(int((x + 1.0) / s.g.spacing[0]), int((y + 1.0) / s.g.spacing[1]), 0));
    };
    flame[cellOf(0.1, 0.45)] = 4.0f;  // in the smoke: the largest flame, full glow
    flame[cellOf(0.0, -0.6)] = 1.0f;  // in clear air: a quarter glow
    const Image image = preview::renderSmoke2D(s.g, s.density, {}, flame, s.mask);
    EXPECT_EQ(s.at(image, 0.1, 0.45), palette::kFlame);
    const Rgba faint = s.at(image, 0.0, -0.6);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(faint[k],
                    palette::kBackground[k] + 0.25 * (palette::kFlame[k] - palette::kBackground[k]),
                    1.0)
            << k;
    // A fixed scale: the same flame glows half as much at twice the scale.
    preview::Smoke2DOptions fixed;
    fixed.flameScale = 8.0;
    const Rgba half =
        s.at(preview::renderSmoke2D(s.g, s.density, {}, flame, s.mask, fixed), 0.0, -0.6);
    EXPECT_LT(brightness(half), brightness(faint));
    EXPECT_GT(brightness(half), brightness(palette::kBackground));
    // Without flame the picture is the smoke's alone.
    EXPECT_EQ(
        preview::renderSmoke2D(s.g, s.density, {}, std::vector<float>(flame.size(), 0.0f), s.mask)
            .rgba,
        preview::renderSmoke2D(s.g, s.density, {}, {}, s.mask).rgba);
    fixed.flameScale = -1.0;
    EXPECT_THROW(preview::renderSmoke2D(s.g, s.density, {}, flame, s.mask, fixed), Error);
    EXPECT_THROW(preview::renderSmoke2D(s.g, s.density, {}, std::vector<float>(3), s.mask), Error);
}

TEST(SmokeImage2DTest, CellsKeepTheirShape) {
    MacGrid g = grid(2, 32);
    g.cells[1] = 8;
    g.spacing[1] = 2.0 * g.spacing[0];  // cells twice as tall as wide
    const Image image = preview::renderSmoke2D(g, std::vector<float>(32 * 8, 0.0f), {}, {}, {});
    EXPECT_EQ(image.width, 512);
    EXPECT_EQ(image.height, 8 * 32);
}

TEST(SmokeImage2DTest, RejectsWrongGridsSizesAndOptions) {
    const Disk2D s;
    EXPECT_THROW(preview::renderSmoke2D(grid(3, 4), std::vector<float>(64), {}, {}, {}), Error);
    EXPECT_THROW(preview::renderSmoke2D(s.g, std::vector<float>(10), {}, {}, s.mask), Error);
    EXPECT_THROW(preview::renderSmoke2D(s.g, s.density, std::vector<float>(3), {}, s.mask), Error);
    preview::Smoke2DOptions bad;
    bad.densityScale = 0.0;
    EXPECT_THROW(preview::renderSmoke2D(s.g, s.density, {}, {}, s.mask, bad), Error);
}

// ------------------------------------------------------------------------------ contact sheet

TEST(ParticleDotsTest, ADotLandsWhereThePictureShowsItsPoint) {
    // 2D: a 16 × 8 smoke grid over [0, 2] × [0, 1] at 4 pixels a cell, y up.
    MacGrid flat;
    flat.dim = 2;
    flat.cells = {16, 8, 1};
    flat.spacing = {0.125, 0.125, 1.0};
    preview::Image picture(64, 32);
    const std::vector<double> points{0.5, 0.25, 0.0, 5.0, 5.0, 0.0};  // the second off the picture
    preview::drawParticles2D(picture, flat, 4, points);
    const preview::Rgba dot = preview::palette::kParticle;
    // x = 0.5 → pixel 16; y = 0.25 → 2 cells up from the bottom, pixel row 32 − 8 = 24.
    EXPECT_EQ(picture.pixel(16, 24), dot);
    EXPECT_NE(picture.pixel(16, 22), dot);
    long coloured = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) coloured += picture.pixel(x, y)[0] > 0;
    EXPECT_EQ(coloured, 5) << "one dot: its pixel and four half-blended beside it";

    // 3D: the box's centre is the middle of the camera's picture; a point behind it is not drawn.
    MacGrid box;
    box.dim = 3;
    box.cells = {8, 8, 8};
    box.spacing = {0.125, 0.125, 0.125};
    const auto view = preview::volumeViewParams(box, 40, 30, 1.0f);
    preview::Image solid(40, 30);
    // The second point lies behind the camera (it looks along −(0.45, −0.78, 0.42)).
    preview::drawParticles3D(solid, box, view,
                             std::vector<double>{0.5, 0.5, 0.5, 45.5, -77.5, 42.5});
    int centres = 0;  // the picture's middle is a pixel corner: the dot's pixel is one of four
    for (int y = 14; y <= 15; ++y)
        for (int x = 19; x <= 20; ++x) centres += solid.pixel(x, y) == dot;
    EXPECT_EQ(centres, 1);
    coloured = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) coloured += solid.pixel(x, y)[0] > 0;
    EXPECT_EQ(coloured, 5);
}

TEST(ContactSheetTest, GridOfThumbnailsWithNumbers) {
    std::vector<Image> frames;
    for (int f = 0; f < 5; ++f)
        frames.emplace_back(512, 384, Rgba{std::uint8_t(40 * f), 100, 200, 255});
    const Image sheet = preview::contactSheet(frames, 3);
    EXPECT_EQ(sheet.width, 3 * (256 + 4) + 4);
    EXPECT_EQ(sheet.height, 2 * (192 + 4) + 4);
    // Frame 4 is the second of row 2; its thumbnail keeps the frame's colour away from the label.
    EXPECT_EQ(sheet.pixel(4 + 260 + 200, 4 + 196 + 150), (Rgba{160, 100, 200, 255}));
    // The label of frame 0 has white digit pixels in the top left corner.
    bool label = false;
    for (int y = 4; y < 4 + 20; ++y)
        for (int x = 4; x < 4 + 20; ++x) label |= sheet.pixel(x, y) == palette::kLabel;
    EXPECT_TRUE(label);
    EXPECT_EQ(preview::contactSheet(std::span(frames).first(2), 3).width, 2 * 260 + 4);
    EXPECT_THROW(preview::contactSheet({}, 3), Error);
    EXPECT_THROW(preview::contactSheet(frames, 0), Error);
}

TEST(ContactSheetTest, EvenlySpacedFramesKeepTheFirstAndTheLast) {
    EXPECT_EQ(preview::evenlySpaced(3, 48), (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(preview::evenlySpaced(5, 3), (std::vector<std::size_t>{0, 2, 4}));
    EXPECT_EQ(preview::evenlySpaced(400, 2), (std::vector<std::size_t>{0, 399}));
    for (const std::size_t count : {49, 50, 97, 400, 100000}) {
        const std::vector<std::size_t> chosen = preview::evenlySpaced(count, 48);
        ASSERT_EQ(chosen.size(), 48u) << count;
        EXPECT_EQ(chosen.front(), 0u);
        EXPECT_EQ(chosen.back(), count - 1);
        for (std::size_t i = 1; i < chosen.size(); ++i) {
            EXPECT_GT(chosen[i], chosen[i - 1]) << count;
            // Steps differ by at most one frame: evenly spaced.
            EXPECT_LE(chosen[i] - chosen[i - 1], (count - 1) / 47 + 1) << count;
        }
    }
    EXPECT_TRUE(preview::evenlySpaced(0, 48).empty());
    EXPECT_THROW(preview::evenlySpaced(10, 1), Error);
}

TEST(PngReaderTest, ReadsWhatTheWriterWroteAndNamesAFileItCannotRead) {
    const testing::TestFolder dir;
    Image picture(5, 3, {10, 20, 30, 255});
    picture.setPixel(4, 2, {200, 100, 50, 128});
    preview::writePng(dir.path() / "a.png", picture);
    const Image read = preview::readPng(dir.path() / "a.png");
    EXPECT_EQ(read.width, 5);
    EXPECT_EQ(read.height, 3);
    EXPECT_EQ(read.rgba, picture.rgba);
    std::ofstream(dir.path() / "b.png") << "not a picture";
    for (const char* name : {"b.png", "missing.png"}) {
        try {
            preview::readPng(dir.path() / name);
            ADD_FAILURE() << name << " was read";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

TEST(ContactSheetTest, AreaResamplingAveragesAndKeepsUniformColours) {
    Image checker(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            checker.setPixel(x, y, (x + y) % 2 ? Rgba{200, 0, 100, 255} : Rgba{0, 200, 100, 255});
    EXPECT_EQ(preview::resampled(checker, 1, 1).pixel(0, 0), (Rgba{100, 100, 100, 255}));
    const Image grown = preview::resampled(Image(3, 5, {9, 8, 7, 255}), 7, 11);
    for (std::size_t p = 0; p < grown.rgba.size(); p += 4) ASSERT_EQ(grown.rgba[p], 9);
}

// ----------------------------------------------------------------------------------------- 3D

class VolumePreviewTest : public testing::VulkanTest {
protected:
    /// The device picture of `density`.
    Image render(const MacGrid& g, const std::vector<float>& density,
                 const std::vector<std::uint8_t>& mask, int w, int h, float scale) {
        preview::VolumeRenderer renderer(context(), g, mask, w, h);
        const vulkan::DeviceBuffer buffer =
            vulkan::DeviceBuffer::fromValues<float>(context(), density, "density");
        return renderer.render(buffer, scale);
    }
};

TEST_P(VolumePreviewTest, DeviceEqualsTheCpuReference) {
    // Not a cube, cells not cubes, a ball domain, smoke crossing its wall, a dense and a thin blob.
    const MacGrid g = grid(3, 24, 30, 0.8);
    const std::vector<std::uint8_t> mask = ballMask(g, 0.85);
    std::vector<float> density = blob(g, 0.2, -0.1, 0.3, 0.3, 2.0);
    const std::vector<float> thin = blob(g, -0.5, 0.4, -0.4, 0.4, 0.3);
    for (std::size_t c = 0; c < density.size(); ++c) density[c] += thin[c];
    for (const auto& [w, h] : {std::pair{160, 120}, std::pair{90, 130}}) {
        const Image device = render(g, density, mask, w, h, 12.0f);
        const Image reference = preview::renderVolumeReference(g, density, mask, w, h, 12.0f);
        ASSERT_EQ(device.width, w);
        ASSERT_EQ(device.height, h);
        const PixelDifference d = compare(device, reference);
        std::cout << w << "x" << h << ": max channel difference " << d.maxAbs
                  << ", pixels over 2: " << 100 * d.overTwo << "%\n";
        EXPECT_LE(d.overTwo, 0.005);
        EXPECT_LE(d.maxAbs, 16);
    }
}

TEST_P(VolumePreviewTest, FlamesGlowOnTheDeviceAsOnTheCpuReference) {
    // A flame low in the smoke: it glows orange (red well above blue) where it shows, dimmed by
    // the smoke in front; without flame values nothing glows; device = CPU reference.
    const MacGrid g = grid(3, 24);
    const std::vector<std::uint8_t> mask = ballMask(g, 0.85);
    const std::vector<float> density = blob(g, 0.0, 0.0, 0.2, 0.4, 1.0);
    const std::vector<float> flame = blob(g, 0.0, 0.0, -0.3, 0.25, 4.0);
    const float glow = 2.0f;
    {
        preview::VolumeRenderer renderer(context(), g, mask, 120, 90);
        const vulkan::DeviceBuffer densityBuffer =
            vulkan::DeviceBuffer::fromValues<float>(context(), density, "density");
        const vulkan::DeviceBuffer flameBuffer =
            vulkan::DeviceBuffer::fromValues<float>(context(), flame, "flame");
        const Image device = renderer.render(densityBuffer, 12.0f, &flameBuffer, glow);
        const Image reference =
            preview::renderVolumeReference(g, density, mask, 120, 90, 12.0f, flame, glow);
        const PixelDifference d = compare(device, reference);
        std::cout << "flame: max channel difference " << d.maxAbs
                  << ", pixels over 2: " << 100 * d.overTwo << "%\n";
        EXPECT_LE(d.overTwo, 0.005);
        EXPECT_LE(d.maxAbs, 16);
        const Image plain = preview::renderVolumeReference(g, density, mask, 120, 90, 12.0f);
        int warmest = 0, warmestPlain = 0;
        for (int y = 0; y < 90; ++y)
            for (int x = 0; x < 120; ++x) {
                warmest = std::max(warmest,
                                   int(reference.pixel(x, y)[0]) - int(reference.pixel(x, y)[2]));
                warmestPlain =
                    std::max(warmestPlain, int(plain.pixel(x, y)[0]) - int(plain.pixel(x, y)[2]));
            }
        std::cout << "red above blue: " << warmest << " with flame, " << warmestPlain
                  << " without\n";
        EXPECT_GT(warmest, 60);
        EXPECT_LT(warmestPlain, 30);
        // No flame buffer: the picture without glow.
        EXPECT_EQ(compare(renderer.render(densityBuffer, 12.0f), plain).maxAbs <= 16, true);
        EXPECT_THROW(renderer.render(densityBuffer, 12.0f, &flameBuffer, -1.0f), Error);
        const vulkan::DeviceBuffer small = vulkan::DeviceBuffer::fromValues<float>(
            context(), std::vector<float>(10, 1.0f), "small flame");
        EXPECT_THROW(renderer.render(densityBuffer, 12.0f, &small, glow), Error);
    }
    EXPECT_THROW(preview::renderVolumeReference(g, density, mask, 120, 90, 12.0f,
                                                std::vector<float>(10), glow),
                 Error);
}

TEST_P(VolumePreviewTest, PeriodicAxesWrapOnTheDeviceAsOnTheCpuReference) {
    // Smoke in the first layer of cells along x and y only: on periodic axes the half cell beyond
    // the last cell centre interpolates towards it, so it shows at the far faces too.
    MacGrid g = grid(3, 20);
    const std::vector<std::uint8_t> mask(std::size_t(g.cellCount()), 1);
    const std::vector<float> layer = cellField(g, [&](double x, double y, double) {
        return x < g.origin[0] + g.spacing[0] || y < g.origin[1] + g.spacing[1] ? 3.0 : 0.0;
    });
    const Image walled = preview::renderVolumeReference(g, layer, mask, 120, 90, 12.0f);
    g.periodic = {true, true, false};
    const Image reference = preview::renderVolumeReference(g, layer, mask, 120, 90, 12.0f);
    const Image device = render(g, layer, mask, 120, 90, 12.0f);
    const PixelDifference d = compare(device, reference);
    std::cout << "periodic x, y: max channel difference " << d.maxAbs
              << ", pixels over 2: " << 100 * d.overTwo << "%\n";
    EXPECT_LE(d.overTwo, 0.005);
    EXPECT_LE(d.maxAbs, 16);
    const PixelDifference wrapped = compare(reference, walled);
    std::cout << "periodic against walled: pixels over 2: " << 100 * wrapped.overTwo << "%\n";
    EXPECT_GT(wrapped.overTwo, 0.01) << "the periodic picture does not wrap";
}

TEST_P(VolumePreviewTest, BlobHighInTheBoxAppearsHigherInThePicture) {
    const MacGrid g = grid(3, 24);
    const std::vector<std::uint8_t> mask(std::size_t(g.cellCount()), 1);
    const Image empty = render(g, std::vector<float>(mask.size(), 0.0f), mask, 96, 96, 10.0f);
    const double high =
        brightRowCentre(render(g, blob(g, 0.0, 0.0, 0.6, 0.25), mask, 96, 96, 10.0f), empty);
    const double low =
        brightRowCentre(render(g, blob(g, 0.0, 0.0, -0.6, 0.25), mask, 96, 96, 10.0f), empty);
    std::cout << "brightness centre row: high blob " << high << ", low blob " << low
              << " (of 96)\n";
    ASSERT_GE(high, 0.0);
    EXPECT_LT(high + 15.0, low);
}

TEST_P(VolumePreviewTest, EmptyVolumeShowsOnlyBackgroundAndOutline) {
    const MacGrid g = grid(3, 16);
    const std::vector<std::uint8_t> all(std::size_t(g.cellCount()), 1);
    const Image image = render(g, std::vector<float>(all.size(), 0.0f), all, 128, 96, 10.0f);
    // Every pixel lies between the background and the outline colour, as one mix of the two.
    const std::array<double, 3> bg{14, 16, 22}, outline{0.45 * 255, 0.5 * 255, 0.6 * 255};
    int background = 0, edge = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Rgba c = image.pixel(x, y);
            if (c == palette::kBackground) {
                ++background;
                continue;
            }
            const double a = (c[2] - bg[2]) / (outline[2] - bg[2]);
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(c[k], bg[k] + a * (outline[k] - bg[k]), 1.5) << x << "," << y;
            edge += a > 0.2;
        }
    EXPECT_GT(background, image.width * image.height * 8 / 10);
    EXPECT_GT(edge, 200);  // 12 box edges, each tens of pixels long
    // A ball domain adds its faint glass, and nothing bright.
    const Image glass =
        render(g, std::vector<float>(all.size(), 0.0f), ballMask(g, 0.8), 128, 96, 10.0f);
    const Rgba middle = glass.pixel(64, 48);
    EXPECT_GT(brightness(middle), brightness(palette::kBackground));
    EXPECT_LT(brightness(middle), 60);
}

TEST_P(VolumePreviewTest, LightFromAboveMakesTheTopOfADenseBlobBrighter) {
    const MacGrid g = grid(3, 32);
    const std::vector<std::uint8_t> mask(std::size_t(g.cellCount()), 1);
    // A ball of uniform density with a crisp edge: its disc in the picture is its surface.
    const std::vector<float> ball = cellField(g, [](double x, double y, double z) {
        return std::clamp((0.5 - std::sqrt(x * x + y * y + z * z)) / 0.05, 0.0, 1.0);
    });
    const Image image = render(g, ball, mask, 128, 128, 40.0f);
    // Down the middle column: the blob's upper and lower quarters.
    std::vector<int> rows;
    for (int y = 0; y < image.height; ++y)
        if (brightness(image.pixel(64, y)) > brightness(palette::kBackground) + 30)
            rows.push_back(y);
    ASSERT_GT(rows.size(), 20u);
    const auto meanOver = [&](std::size_t begin, std::size_t end) {
        double sum = 0.0;
        for (std::size_t i = begin; i < end; ++i) sum += brightness(image.pixel(64, rows[i]));
        return sum / double(end - begin);
    };
    const std::size_t quarter = rows.size() / 4;
    const double top = meanOver(0, quarter), bottom = meanOver(rows.size() - quarter, rows.size());
    std::cout << "blob top " << top << ", bottom " << bottom << "\n";
    EXPECT_GT(top, bottom + 50.0);
}

TEST_P(VolumePreviewTest, RejectsWrongGridsAndBuffers) {
    EXPECT_THROW(preview::VolumeRenderer(context(), grid(2, 8), {}, 16, 16), Error);
    const MacGrid g = grid(3, 8);
    EXPECT_THROW(preview::VolumeRenderer(context(), g, std::vector<std::uint8_t>(7, 1), 16, 16),
                 Error);
    EXPECT_THROW(preview::VolumeRenderer(context(), g, {}, 0, 16), Error);
    preview::VolumeRenderer renderer(context(), g, {}, 16, 16);
    const vulkan::DeviceBuffer small(context(), 64, "small");
    EXPECT_THROW(renderer.render(small, 1.0f), Error);
    const vulkan::DeviceBuffer enough(context(), 512 * sizeof(float), "enough");
    EXPECT_THROW(renderer.render(enough, -1.0f), Error);
}

/// A 64³ grid at 512 × 512, the sample picture (preview_3d.png in the artifact folder): the same
/// pixels from every render and from a timed command sequence. Its time: tools/bench/bench_preview.
TEST_P(VolumePreviewTest, Renders64CubedAt512SquaredTheSameEachTime) {
    const MacGrid g = grid(3, 64);
    preview::VolumeRenderer renderer(context(), g, ballMask(g, 0.95), 512, 512);
    const vulkan::DeviceBuffer buffer =
        vulkan::DeviceBuffer::fromValues<float>(context(), testing::mushroomCloud(g), "density");
    const Image image = renderer.render(buffer, 15.0f);
    const Image empty = render(g, std::vector<float>(std::size_t(g.cellCount()), 0.0f),
                               ballMask(g, 0.95), 512, 512, 15.0f);
    EXPECT_GT(brightRowCentre(image, empty), 0.0) << "the cloud does not show";
    EXPECT_EQ(renderer.render(buffer, 15.0f).rgba, image.rgba);
    vulkan::CommandSequence timed(context(), true);
    renderer.record(timed, buffer, 15.0f);
    timed.submitAndWait();
    EXPECT_EQ(renderer.picture().rgba, image.rgba);
    preview::writePng(testing::artifactFolder() / "preview_3d.png", image);
}

TEST_P(VolumePreviewTest, StagedBuffersGiveTheSamePicture) {
    // Discrete GPUs keep buffers in device-local memory behind staging copies: force that here.
    vulkan::VulkanContextOptions options;
    options.validation = GetParam();
    options.forceStaging = true;
    const vulkan::VulkanContext staged(options);
    const MacGrid g = grid(3, 20);
    const std::vector<std::uint8_t> mask = ballMask(g, 0.9);
    const std::vector<float> density = blob(g, 0.1, 0.0, 0.2, 0.3);
    Image picture;
    {
        preview::VolumeRenderer renderer(staged, g, mask, 64, 48);
        const auto buffer = vulkan::DeviceBuffer::fromValues<float>(staged, density, "density");
        picture = renderer.render(buffer, 10.0f);
    }
    EXPECT_EQ(picture.rgba, render(g, density, mask, 64, 48, 10.0f).rgba);
    EXPECT_EQ(staged.validationMessageCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Vulkan, VolumePreviewTest, ::testing::Bool(), testing::validationName);

}  // namespace
}  // namespace modeflow
