/// @file SeparableTransformKernelTest.cpp
/// The closed-form basis transforms on the device (engine/device/SeparableTransform: per-axis
/// sums in shaders/separable_*.comp) against the CPU reference (engine/reference on
/// engine/basis/SeparableTransform, FFTW) in float32: reconstruction, projection of a force
/// density and of a face field, on wall boxes, a torus and mixed axes, 2D and 3D, with and
/// without the validation layer.

#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "engine/device/SeparableTransform.h"
#include "engine/reference/ForceProjection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/WholeBoxDofs.h"
#include "tests/support/KernelTestSupport.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/TestScenes.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using vulkan::CommandSequence;
using vulkan::DeviceBuffer;

struct Case {
    std::string name;
    BasisCache cache;
};

BasisCache closedForm(std::array<int, 3> res, int dim, std::array<bool, 3> periodic, int modes) {
    BasisCache cache;
    cache.grid = testing::gridScene(res, {0.0, -0.5, 0.25}, {1.0, 0.4, 1.0}, dim).grid;
    cache.grid.periodic = periodic;
    fillWholeBoxDofs(cache);
    const ClosedFormVelocity basis = closedFormVelocityBasis(cache.grid, {{1, modes}});
    cache.velocity.source = BasisSource::ClosedForm;
    cache.velocity.eigenvalues = basis.eigenvalues;
    cache.velocity.separable = basis.modes;
    return cache;
}

const std::vector<Case>& cases() {
    static const std::vector<Case> all{
        {"2D box 24x20", closedForm({24, 20, 1}, 2, {false, false, false}, 60)},
        {"2D channel 16x12", closedForm({16, 12, 1}, 2, {true, false, false}, 40)},
        {"3D box 12x10x9", closedForm({12, 10, 9}, 3, {false, false, false}, 120)},
        {"3D torus 8x6x7", closedForm({8, 6, 7}, 3, {true, true, true}, 90)},
        {"3D mixed 7x8x6", closedForm({7, 8, 6}, 3, {false, true, false}, 90)},
    };
    return all;
}

Eigen::VectorXd asVector(const std::vector<double>& values) {
    return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
}

class SeparableTransformKernelTest : public testing::VulkanTest {};

/// A case's sizes, its kernels and a random modal state on the device.
struct WithState {
    WithState(const vulkan::VulkanContext& context, const Case& c, int seed)
        : modes(Eigen::Index(c.cache.velocity.separable.size())),
          dofs(Eigen::Index(c.cache.faces.size())),
          kernels(context, c.cache),
          grid(MacGrid::fromSpec(c.cache.grid)),
          state(testing::stateBuffer(context, testing::randomVector(modes, seed))) {}
    Eigen::Index modes, dofs;
    device::SeparableTransformKernels kernels;
    MacGrid grid;
    DeviceBuffer state;
};

TEST_P(SeparableTransformKernelTest, ReconstructionEqualsTheCpuReference) {
    for (const Case& c : cases()) {
        const auto modes = Eigen::Index(c.cache.velocity.separable.size());
        const device::SeparableTransformKernels kernels(context(), c.cache);
        const Eigen::VectorXd v = testing::randomVector(modes, 7);
        const DeviceBuffer state = testing::stateBuffer(context(), v);
        const MacGrid grid = MacGrid::fromSpec(c.cache.grid);
        // DOF faces start as NaN (a face never written shows), the others as 0 (and stay so).
        std::vector<float> initial(std::size_t(grid.faceTotal()), 0.0f);
        for (const std::int64_t f : c.cache.faces)
            initial[std::size_t(f)] = std::numeric_limits<float>::quiet_NaN();
        DeviceBuffer field = DeviceBuffer::fromValues<float>(context(), initial, "face field");
        CommandSequence sequence(context());
        kernels.recordReconstruction(sequence, state, field);
        sequence.submitAndWait();
        const Eigen::VectorXd device = testing::downloadFloats(field, initial.size());
        ASSERT_FALSE(device.hasNaN()) << c.name << ": a DOF face was never written";
        const Eigen::VectorXd reference = asVector(reference::reconstructFaceField(c.cache, v));
        for (Eigen::Index f = 0; f < device.size(); ++f) {
            if (initial[std::size_t(f)] == 0.0f) {
                EXPECT_EQ(device[f], 0.0) << c.name << ": face " << f;
            }
        }
        const double error = testing::relativeError(device, reference);
        std::cout << c.name << ": reconstruction relative error " << error << "\n";
        EXPECT_LE(error, 1e-5) << c.name;
    }
}

TEST_P(SeparableTransformKernelTest, ProjectionsEqualTheCpuReference) {
    for (const Case& c : cases()) {
        const auto modes = Eigen::Index(c.cache.velocity.separable.size());
        const auto dofs = Eigen::Index(c.cache.faces.size());
        const device::SeparableTransformKernels kernels(context(), c.cache);
        const MacGrid grid = MacGrid::fromSpec(c.cache.grid);
        // A force density per DOF, and the same values as a face field's at the DOFs.
        const Eigen::VectorXd q = testing::randomVector(dofs, 11);
        std::vector<double> faceField(std::size_t(grid.faceTotal()), 1e3);
        for (Eigen::Index d = 0; d < dofs; ++d)
            faceField[std::size_t(c.cache.faces[std::size_t(d)])] = q[d];
        const DeviceBuffer density =
            DeviceBuffer::fromValues<float>(context(), testing::toFloat(q), "density");
        DeviceBuffer f1(context(), std::size_t(modes) * sizeof(float), "f density");
        DeviceBuffer f2(context(), std::size_t(modes) * sizeof(float), "f field");
        CommandSequence sequence(context());
        kernels.recordProjection(sequence, density, f1);
        kernels.recordFaceFieldProjection(sequence, density, f2);
        sequence.submitAndWait();
        const Eigen::VectorXd byDensity =
            reference::projectForce(c.cache, q, FaceQuantity::Density);
        const Eigen::VectorXd byField = reference::projectFaceField(c.cache, faceField);
        const double e1 =
            testing::relativeError(testing::downloadFloats(f1, std::size_t(modes)), byDensity);
        const double e2 =
            testing::relativeError(testing::downloadFloats(f2, std::size_t(modes)), byField);
        std::cout << c.name << ": projection relative error " << e1 << " (density), " << e2
                  << " (face field)\n";
        EXPECT_LE(e1, 1e-5) << c.name;
        EXPECT_LE(e2, 1e-5) << c.name;
    }
}

TEST_P(SeparableTransformKernelTest, AComponentsProjectionEqualsTheWholeOneOfItsField) {
    // Buoyancy without splats: q on one component's DOFs only, the others' passes skipped and
    // their slots zeroed (a reconstruction first leaves the slots full of other values).
    for (const Case& c : cases()) {
        const WithState setup(context(), c, 13);
        const auto& [modes, dofs, kernels, grid, state] = setup;
        DeviceBuffer field(context(), std::size_t(grid.faceTotal()) * sizeof(float), "field");
        for (int component = 0; component < c.cache.grid.dim; ++component) {
            Eigen::VectorXd q = testing::randomVector(dofs, 17 + component);
            for (Eigen::Index d = 0; d < dofs; ++d) {
                const std::int64_t face = c.cache.faces[std::size_t(d)];
                if (face < grid.faceOffset(component) || face >= grid.faceOffset(component + 1))
                    q[d] = 0.0;
            }
            const DeviceBuffer density =
                DeviceBuffer::fromValues<float>(context(), testing::toFloat(q), "density");
            DeviceBuffer f(context(), std::size_t(modes) * sizeof(float), "f");
            CommandSequence sequence(context());
            kernels.recordReconstruction(sequence, state, field);
            kernels.recordComponentProjection(sequence, density, component, f);
            sequence.submitAndWait();
            const double error =
                testing::relativeError(testing::downloadFloats(f, std::size_t(modes)),
                                       reference::projectForce(c.cache, q, FaceQuantity::Density));
            EXPECT_LE(error, 1e-5) << c.name << ", component " << component;
        }
        CommandSequence sequence(context());
        DeviceBuffer f(context(), std::size_t(modes) * sizeof(float), "f");
        EXPECT_THROW(kernels.recordComponentProjection(sequence, field, c.cache.grid.dim, f),
                     Error);
    }
    expectNoValidationMessages();
}

/// Whether `face` lies on a side of a cell of `box` (wrapping along periodic axes).
bool onBoxSide(const MacGrid& grid, const CellBox& box, std::int64_t face) {
    const FaceLocation at = locateFace(grid, face);
    for (int a = 0; a < grid.dim; ++a) {
        const int n = grid.cells[a], extent = box.count[a] + (a == at.axis ? 1 : 0);
        int offset = at.pos[a] - box.first[a];
        if (grid.periodic[a]) offset = ((offset % n) + n) % n;
        if (offset < 0 || offset >= extent) return false;
    }
    return true;
}

TEST_P(SeparableTransformKernelTest, TransformsOnABoxEqualTheWholeOnes) {
    // An obstacle's mismatch, zero off a box, and the velocity it needs, on that box: the
    // passes take the box's lines (and inputs, or outputs) alone. Boxes inside,
    // against the low and the high sides, past the high side, and across periodic seams; the
    // scratch first holds a reconstruction's values.
    for (const Case& c : cases()) {
        const WithState setup(context(), c, 19);
        const auto& [modes, dofs, kernels, grid, state] = setup;
        DeviceBuffer field(context(), std::size_t(grid.faceTotal()) * sizeof(float), "field");
        const int z = grid.dim == 3 ? 1 : 0;
        const std::vector<CellBox> boxes{
            {{2, 1, z}, {3, 4, grid.dim == 3 ? 3 : 1}},
            {{0, 0, 0}, {2, 3, grid.dim == 3 ? 2 : 1}},
            {{grid.cells[0] - 2, grid.cells[1] - 3, 0}, {2, 3, grid.cells[2]}},
            {{grid.cells[0] - 1, 1, 0}, {4, 2, grid.dim == 3 ? 2 : 1}},
            {{-2, -1, -z}, {4, 3, grid.dim == 3 ? 3 : 1}}};
        for (std::size_t b = 0; b < boxes.size(); ++b) {
            CellBox box = boxes[b];
            for (int a = 0; a < 3; ++a) {
                // A walled axis's box stays on the grid; a periodic one's wraps.
                if (grid.periodic[a]) continue;
                const int last = std::min(box.first[a] + box.count[a], grid.cells[a]);
                box.first[a] = std::max(box.first[a], 0);
                box.count[a] = std::max(last - box.first[a], 1);
            }
            Eigen::VectorXd q = testing::randomVector(dofs, 23 + int(b));
            Eigen::Index inside = 0;
            for (Eigen::Index d = 0; d < dofs; ++d) {
                if (onBoxSide(grid, box, c.cache.faces[std::size_t(d)]))
                    ++inside;
                else
                    q[d] = 0.0;
            }
            ASSERT_GT(inside, 0) << c.name << ", box " << b;
            const DeviceBuffer values =
                DeviceBuffer::fromValues<float>(context(), testing::toFloat(q), "mismatch");
            DeviceBuffer whole(context(), std::size_t(modes) * sizeof(float), "whole");
            DeviceBuffer windowed(context(), std::size_t(modes) * sizeof(float), "windowed");
            CommandSequence sequence(context());
            kernels.recordFaceFieldProjection(sequence, values, whole);
            kernels.recordReconstruction(sequence, state, field);
            kernels.recordFaceFieldProjection(sequence, values, windowed, &box);
            sequence.submitAndWait();
            const Eigen::VectorXd expected = testing::downloadFloats(whole, std::size_t(modes));
            EXPECT_LE(testing::relativeError(testing::downloadFloats(windowed, std::size_t(modes)),
                                             expected),
                      1e-6)
                << c.name << ", box " << b;
            EXPECT_GT(expected.norm(), 0.0);

            // A reconstruction needed on the box alone: its faces as the whole one's, to the bit.
            std::vector<float> nan(std::size_t(grid.faceTotal()),
                                   std::numeric_limits<float>::quiet_NaN());
            DeviceBuffer part = DeviceBuffer::fromValues<float>(context(), nan, "part");
            CommandSequence again(context());
            kernels.recordReconstruction(again, state, field);
            kernels.recordReconstruction(again, state, part, &box);
            again.submitAndWait();
            const Eigen::VectorXd all = testing::downloadFloats(field, nan.size());
            const Eigen::VectorXd some = testing::downloadFloats(part, nan.size());
            for (const std::int64_t face : c.cache.faces) {
                if (onBoxSide(grid, box, face)) {
                    EXPECT_EQ(some[face], all[face])
                        << c.name << ", box " << b << ", face " << face;
                }
            }
        }
    }
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, SeparableTransformKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
