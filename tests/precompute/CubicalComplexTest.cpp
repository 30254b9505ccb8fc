#include <gtest/gtest.h>

#include <array>

#include <Eigen/Dense>

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

GridSpec periodicGrid(int dim, std::array<bool, 3> periodic) {
    GridSpec g = grid(dim);
    g.periodic = periodic;
    return g;
}

TEST(CubicalComplexPeriodic, PeriodicAxesHoldNPositionsOfEveryElementType) {
    // 2D, x periodic: vertices 5 x 5, x-edges (normal y) 5 x 5, y-edges (normal x) 5 x 4.
    const CubicalComplex c2(periodicGrid(2, {true, false, false}));
    EXPECT_EQ(c2.count(0), 5 * 5);
    EXPECT_EQ(c2.count(1), 5 * 4 + 5 * 5);
    EXPECT_EQ(c2.count(2), 20);
    // 3D torus: 3N faces and edges, N vertices.
    const CubicalComplex c3(periodicGrid(3, {true, true, true}));
    for (int k = 0; k <= 3; ++k)
        EXPECT_EQ(c3.count(k), (k == 0 || k == 3 ? 1 : 3) * 60) << "k " << k;
    for (int k = 0; k <= 3; ++k)
        for (std::int64_t i = 0; i < c3.count(k); ++i) ASSERT_EQ(c3.index(c3.element(k, i)), i);
}

TEST(CubicalComplexPeriodic, IncidenceWrapsAcrossTheSeam) {
    for (int dim : {2, 3}) {
        const CubicalComplex c(periodicGrid(dim, {true, dim == 3, false}));
        const SparseMatrix d = c.incidence(dim - 1);
        // The last cell along x: its upper x face is face 0, the first cell's lower face.
        const Element last{(1u << dim) - 1, {4 - (dim == 3), 1, 0}};
        const unsigned xFace = ((1u << dim) - 1) & ~1u;
        const Element seam{xFace, {0, 1, 0}}, lower{xFace, last.pos};
        EXPECT_EQ(d.coeff(c.index(last), c.index(seam)), 1.0) << dim << "D";
        EXPECT_EQ(d.coeff(c.index(last), c.index(lower)), -1.0) << dim << "D";
        EXPECT_EQ(d.coeff(c.index(Element{last.axes, {0, 1, 0}}), c.index(seam)), -1.0)
            << dim << "D";
        // Every cell has 2·dim faces, every face two cells along a periodic normal.
        for (std::int64_t cell = 0; cell < c.count(dim); ++cell)
            ASSERT_EQ(SparseMatrix(d.row(cell)).nonZeros(), 2 * dim) << dim << "D cell " << cell;
        EXPECT_FALSE(c.onWall(seam));
        const unsigned wallFace =
            ((1u << dim) - 1) & ~(1u << (dim - 1));  // the last axis is walled
        EXPECT_TRUE(c.onWall(Element{wallFace, {0, 0, 0}}));
        for (int k = 0; k + 2 <= dim; ++k)
            EXPECT_EQ((c.incidence(k + 1) * c.incidence(k)).norm(), 0.0)
                << dim << "D, d" << k + 1 << " d" << k;
    }
}

/// Elements of dimension k off the box's boundary.
std::vector<std::int64_t> interior(const CubicalComplex& c, int k) {
    std::vector<std::int64_t> ids;
    for (std::int64_t i = 0; i < c.count(k); ++i)
        if (!c.onWall(c.element(k, i))) ids.push_back(i);
    return ids;
}

/// The count of harmonic fluxes (free-slip): the cohomology of the (n−1)-cochains off the box's
/// boundary, faces − rank d_{n−1} − rank d_{n−2} restricted to interior elements.
int harmonicFluxes(const CubicalComplex& c) {
    const int n = c.dim();
    const std::vector<std::int64_t> faces = interior(c, n - 1), vorticity = interior(c, n - 2);
    const Eigen::MatrixXd div = Eigen::MatrixXd(c.incidence(n - 1));
    const Eigen::MatrixXd curl = Eigen::MatrixXd(c.incidence(n - 2));
    Eigen::MatrixXd divOnFaces(div.rows(), Eigen::Index(faces.size()));
    Eigen::MatrixXd curlOnFaces(Eigen::Index(faces.size()), Eigen::Index(vorticity.size()));
    for (std::size_t i = 0; i < faces.size(); ++i) {
        divOnFaces.col(Eigen::Index(i)) = div.col(faces[i]);
        for (std::size_t j = 0; j < vorticity.size(); ++j)
            curlOnFaces(Eigen::Index(i), Eigen::Index(j)) = curl(faces[i], vorticity[j]);
    }
    const auto rank = [](const Eigen::MatrixXd& m) {
        return int(Eigen::FullPivLU<Eigen::MatrixXd>(m).rank());
    };
    return int(faces.size()) - rank(divOnFaces) - rank(curlOnFaces);
}

TEST(CubicalComplexPeriodic, CohomologyCountsOneFluxPerPeriodicAxis) {
    EXPECT_EQ(harmonicFluxes(CubicalComplex(grid(2))), 0);
    EXPECT_EQ(harmonicFluxes(CubicalComplex(periodicGrid(2, {true, false, false}))), 1);
    EXPECT_EQ(harmonicFluxes(CubicalComplex(periodicGrid(2, {true, true, false}))), 2);
    EXPECT_EQ(harmonicFluxes(CubicalComplex(periodicGrid(3, {false, true, false}))), 1);
    EXPECT_EQ(harmonicFluxes(CubicalComplex(periodicGrid(3, {true, true, true}))), 3);
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
