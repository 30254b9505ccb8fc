#include <gtest/gtest.h>

#include <array>

#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/SimplexFraction.h"

namespace modeflow {
namespace {

GridSpec grid(int dim) {
    GridSpec g;
    g.dim = dim;
    g.resolution = dim == 2 ? std::array<int, 3>{5, 4, 1} : std::array<int, 3>{4, 3, 5};
    return g;
}

TEST(CubicalComplex, CountsMatchTheGrid) {
    const CubicalComplex c2(grid(2));
    EXPECT_EQ(c2.count(0), 6 * 5);
    EXPECT_EQ(c2.count(1), 6 * 4 + 5 * 5);
    EXPECT_EQ(c2.count(2), 20);
    const CubicalComplex c3(grid(3));
    EXPECT_EQ(c3.count(0), 5 * 4 * 6);
    EXPECT_EQ(c3.count(1), 4 * 4 * 6 + 5 * 3 * 6 + 5 * 4 * 5);
    EXPECT_EQ(c3.count(2), 5 * 3 * 5 + 4 * 4 * 5 + 4 * 3 * 6);
    EXPECT_EQ(c3.count(3), 60);
}

TEST(CubicalComplex, IndexAndElementAreInverse) {
    const CubicalComplex c(grid(3));
    for (int k = 0; k <= 3; ++k)
        for (std::int64_t i = 0; i < c.count(k); ++i) ASSERT_EQ(c.index(c.element(k, i)), i);
}

TEST(CubicalComplex, ExteriorDerivativeSquaresToZero) {
    for (int dim : {2, 3}) {
        const CubicalComplex c(grid(dim));
        for (int k = 0; k + 2 <= dim; ++k) {
            const SparseMatrix dd = c.incidence(k + 1) * c.incidence(k);
            EXPECT_EQ(dd.norm(), 0.0) << "dim " << dim << ", d" << k + 1 << " d" << k;
        }
    }
}

TEST(CubicalComplex, DivergenceIsOutflowAlongPositiveNormals) {
    for (int dim : {2, 3}) {
        const CubicalComplex c(grid(dim));
        const SparseMatrix d = c.incidence(dim - 1);
        // Interior cell: +1 on its upper face and -1 on its lower face along every axis.
        const Element cell{(1u << dim) - 1, {1, 1, dim == 3 ? 1 : 0}};
        const std::int64_t row = c.index(cell);
        for (int a = 0; a < dim; ++a) {
            const unsigned faceAxes = ((1u << dim) - 1) & ~(1u << a);
            Element lower{faceAxes, cell.pos}, upper{faceAxes, cell.pos};
            ++upper.pos[a];
            EXPECT_EQ(d.coeff(row, c.index(lower)), -1.0) << "axis " << a;
            EXPECT_EQ(d.coeff(row, c.index(upper)), 1.0) << "axis " << a;
        }
    }
}

TEST(SimplexFraction, ExactForLinearFunctions) {
    // Segment: zero at 1/4.
    EXPECT_DOUBLE_EQ(positiveFraction(std::array{1.0, -3.0}), 0.25);
    // Triangle with one positive corner: a²/((a-b)(a-c)).
    EXPECT_DOUBLE_EQ(positiveFraction(std::array{1.0, -1.0, -1.0}), 0.25);
    EXPECT_DOUBLE_EQ(positiveFraction(std::array{-1.0, 1.0, 1.0}), 0.75);
    // Tetrahedron, plane through the midpoints of four edges: half the volume by symmetry.
    EXPECT_NEAR(positiveFraction(std::array{1.0, 1.0, -1.0, -1.0}), 0.5, 1e-15);
    EXPECT_NEAR(positiveFraction(std::array{1.0, -1.0, -1.0, -1.0}), 0.125, 1e-15);
    // Asymmetric 2+2 case against Monte Carlo-free reference: complement identity.
    const std::array v{0.3, 1.7, -0.2, -2.5};
    const std::array w{-0.3, -1.7, 0.2, 2.5};
    EXPECT_NEAR(positiveFraction(v) + positiveFraction(w), 1.0, 1e-14);
    EXPECT_EQ(positiveFraction(std::array{0.0, 0.0, 0.0}), 0.0);
    EXPECT_EQ(positiveFraction(std::array{1e-300, 2.0, 3.0, 4.0}), 1.0);
}

}  // namespace
}  // namespace modeflow
