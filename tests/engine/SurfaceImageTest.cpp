/// Pictures of a surface's dye (engine/preview/SurfaceImage): the surface fills the middle of the
/// picture over the background, dyed parts are orange and the rest pale grey, and hidden
/// triangles never show through.

#include <gtest/gtest.h>

#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/SurfaceImage.h"
#include "precompute/geometry/MeshGenerator.h"

namespace modeflow {
namespace {

TEST(SurfaceImage, DyedHalfIsOrangeTheRestGreyOverTheBackground) {
    const TriangleMesh sphere = makeIcosphere(4);
    std::vector<double> dye;
    for (const Vec3& p : sphere.vertices) dye.push_back(p[2] > 0.0 ? 1.0 : 0.0);  // the upper half
    const preview::Image image = preview::surfaceImage(sphere, dye, 1.0, 200, 200);
    const preview::Rgba corner = image.pixel(2, 2), top = image.pixel(100, 60),
                        bottom = image.pixel(100, 170);
    EXPECT_EQ(corner, (preview::Rgba{14, 16, 22, 255})) << "the background";
    // Orange: red well above blue; grey: red and blue close.
    EXPECT_GT(int(top[0]) - int(top[2]), 80)
        << "the dyed top " << int(top[0]) << "," << int(top[1]) << "," << int(top[2]);
    EXPECT_LT(std::abs(int(bottom[0]) - int(bottom[2])), 30)
        << "the clean bottom " << int(bottom[0]) << "," << int(bottom[1]) << "," << int(bottom[2]);
    EXPECT_GT(int(bottom[0]), 40) << "the bottom is not drawn";
}

TEST(SurfaceImage, RefusesDyeOfTheWrongSize) {
    const TriangleMesh sphere = makeIcosphere(1);
    EXPECT_THROW(preview::surfaceImage(sphere, std::vector<double>(3, 0.0), 1.0, 64, 64), Error);
}

}  // namespace
}  // namespace modeflow
