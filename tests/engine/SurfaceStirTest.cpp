/// `modeflow stir` on a surface (engine/stir/SurfaceStirScene), without a window: the pointer's
/// ray picks the sphere where the picture shows it, a splat's force is tangent to the surface
/// and drives the flow along its direction, a scripted drag over the sphere (the stir loop on a
/// NullScreen) sets a fluid at rest moving and carries the dye along the drag, while a drag off
/// the mesh adds nothing; on both backends.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "engine/display/NullScreen.h"
#include "engine/run/Backend.h"
#include "engine/stir/StirApp.h"
#include "engine/stir/SurfaceStirScene.h"
#include "engine/surface/SurfaceForce.h"
#include "tests/support/SurfaceRuns.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow::testing {
namespace {

/// The unit sphere (642 vertices), modes l = 1..3, a dye source at the north pole for the first
/// 0.4 s, the fluid at rest; once per process.
const RunInputs& sphereRun() {
    static const RunInputs run = icosphereRun({});
    return run;
}

/// The dye's centre of mass (its positive part) on the sphere.
Vec3 dyeCentroid(const std::vector<double>& dye) {
    const std::vector<Vec3>& x = sphereRun().cache.surface.mesh.vertices;
    Vec3 sum{};
    double weight = 0.0;
    for (std::size_t v = 0; v < x.size(); ++v) {
        const double w = std::max(0.0, dye[v]);
        for (int k = 0; k < 3; ++k) sum[k] += w * x[v][k];
        weight += w;
    }
    for (double& s : sum) s /= weight;
    return sum;
}

/// A left drag across the window at height y from x0 to x1 (fractions), from 0.1 s to 0.4 s.
std::string dragAt(double y, double x0, double x1) {
    std::ostringstream s;
    s << "0.10 down " << x0 << " " << y << "\n";
    for (int i = 1; i <= 6; ++i)
        s << 0.10 + 0.05 * i << " move " << x0 + (x1 - x0) * i / 6.0 << " " << y << "\n";
    s << "0.45 up " << x1 << " " << y << "\n";
    return s.str();
}

class SurfaceStir : public ::testing::TestWithParam<BackendKind> {
protected:
    void SetUp() override {
        mContext = makeVulkanContext(true);
        ASSERT_NE(mContext, nullptr);
        mBackend = std::make_unique<Backend>(GetParam(), *mContext);
    }

    /// 40 frames of the sphere on the backend with `script`, on `screen`.
    stir::StirReport run(display::NullScreen& screen, const std::string& script) {
        stir::StirOptions options;
        options.backend.kind = GetParam();
        options.frames = 40;
        options.statistics = false;
        options.script = stir::parseInputScript(script, "test script");
        std::ostringstream log;
        return stir::runStir(options, sphereRun(), screen, log);
    }

    std::unique_ptr<vulkan::VulkanContext> mContext;
    std::unique_ptr<Backend> mBackend;
};

TEST_P(SurfaceStir, PointerPicksTheSphereWhereThePictureShowsIt) {
    stir::SurfaceStirScene scene(*mBackend, sphereRun(), {}, *mContext);
    const stir::SurfaceView& view = scene.view();
    // The picture's centre: the sphere's point facing the viewer (a vertex-free spot of a
    // 642-vertex sphere lies within 0.02 of the unit sphere).
    const auto centre = view.pick(0.5, 0.5, 640, 480);
    ASSERT_TRUE(centre);
    const preview::SurfaceProjection p = view.projection();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(centre->point[k], p.view()[k], 0.02) << k;
    const auto onPicture = p.toPicture(centre->point);
    EXPECT_NEAR(onPicture[0], 320.0, 1e-6);
    EXPECT_NEAR(onPicture[1], 240.0, 1e-6);
    EXPECT_FALSE(view.pick(0.02, 0.02, 640, 480)) << "the corner is off the sphere";
    // In a wider window the picture is letterboxed: the margin misses, the centre still hits.
    EXPECT_FALSE(view.pick(0.05, 0.5, 1280, 480));
    EXPECT_TRUE(view.pick(0.5, 0.5, 1280, 480));
}

TEST_P(SurfaceStir, SplatForceIsTangentAndDrivesTheFlowAlongIt) {
    const BasisCache& cache = sphereRun().cache;
    const SurfaceForce force(cache);
    // On the equator at +x: east (+y) is tangent, +x is the normal.
    const ForceSplat east{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.2};
    const ForceSplat normal{{1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0.2};
    const Eigen::VectorXd f = force.project(std::span(&east, 1));
    const Eigen::VectorXd n = force.project(std::span(&normal, 1));
    EXPECT_LT(n.norm(), 0.02 * f.norm()) << "a normal push reaches the flow: " << n.norm()
                                         << " against a tangent one's " << f.norm();
    // The flow the force starts, u = Σ f_k u_k, runs east at the splat's centre.
    std::size_t nearest = 0;
    for (std::size_t v = 0; v < cache.surface.mesh.vertices.size(); ++v)
        if (cache.surface.mesh.vertices[v][0] > cache.surface.mesh.vertices[nearest][0])
            nearest = v;
    const Eigen::Vector3d u =
        cache.surface.vertexVelocity.middleRows(Eigen::Index(3 * nearest), 3) * f;
    EXPECT_GT(u[1], 0.9 * u.norm()) << "velocity " << u.transpose() << " at the splat";
    EXPECT_EQ(force.project({}).norm(), 0.0);
}

TEST_P(SurfaceStir, DragOverTheSphereStirsTheFluidAndCarriesTheDyeAlong) {
    // The drag passes the north pole's dye from left to right across the picture (the pole
    // shows near the top, at y ≈ 0.09).
    display::NullScreen still(*mContext, 640, 480), stirred(*mContext, 640, 480);
    const stir::StirReport none = run(still, "");
    const stir::StirReport drag = run(stirred, dragAt(0.15, 0.3, 0.7));
    EXPECT_EQ(none.validationMessages + drag.validationMessages, 0u);
    ASSERT_EQ(drag.smoke.density.size(), sphereRun().cache.surface.mesh.vertices.size());
    // Along the picture's right, in the scene.
    stir::SurfaceStirScene scene(*mBackend, sphereRun(), {}, *mContext);
    const preview::SurfaceProjection p = scene.view().projection();
    const auto right = [&](const Vec3& x) { return p.toPicture(x)[0]; };
    const double moved =
        right(dyeCentroid(drag.smoke.density)) - right(dyeCentroid(none.smoke.density));
    EXPECT_GT(moved, 15.0) << "picture pixels the dye moved to the right";
    // The picture shows it.
    const preview::Image &a = still.lastPicture(), &b = stirred.lastPicture();
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) differing += a.rgba[i] != b.rgba[i];
    EXPECT_GT(differing, 1000u);
}

TEST_P(SurfaceStir, DragStartsAFluidAtRestAndADragOffTheMeshAddsNothing) {
    stir::SurfaceStirScene scene(*mBackend, sphereRun(), {}, *mContext);
    const VkExtent2D window{640, 480};
    // Off the sphere, in the corner: no energy, however the pointer moves.
    scene.press(0.02, 0.02, window);
    scene.moveTo(0.1, 0.05, window);
    scene.advance(2, 0.05);
    scene.release();
    EXPECT_EQ(scene.energy(), 0.0);
    // Across the sphere's middle.
    scene.press(0.4, 0.5, window);
    scene.moveTo(0.6, 0.5, window);
    scene.advance(2, 0.05);
    EXPECT_GT(scene.energy(), 1e-3);
    const double stirred = scene.energy();
    scene.release();
    scene.reset();
    EXPECT_EQ(scene.energy(), 0.0) << "after reset";
    EXPECT_GT(stirred, 0.0);
    // The loop: a scripted drag off the mesh leaves the run as it was without one.
    display::NullScreen still(*mContext, 640, 480), missed(*mContext, 640, 480);
    const stir::StirReport none = run(still, "");
    const stir::StirReport offMesh = run(missed, dragAt(0.03, 0.05, 0.25));
    EXPECT_EQ(offMesh.smoke.density, none.smoke.density);
}

INSTANTIATE_TEST_SUITE_P(Backends, SurfaceStir,
                         ::testing::Values(BackendKind::CpuReference, BackendKind::Vulkan),
                         [](const auto& info) {
                             return info.param == BackendKind::Vulkan ? "Vulkan" : "Cpu";
                         });

}  // namespace
}  // namespace modeflow::testing
