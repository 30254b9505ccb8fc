/// Surface DEC and bases (precompute/surface): the operators' identities, the sphere's spectrum
/// l(l+1) with multiplicity 2l+1 converging at second order, the harmonic fields counting the
/// genus, orthonormal and divergence-free bases, and structural coefficients converging to the
/// continuum integral.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <iostream>
#include <random>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "precompute/geometry/MeshGenerator.h"
#include "precompute/surface/SurfaceBasis.h"
#include "precompute/surface/SurfaceCoefficients.h"

namespace modeflow {
namespace {

SurfaceDec decOf(const TriangleMesh& mesh) {
    return buildSurfaceDec(mesh, checkClosedSurface(mesh, "test mesh"));
}

SurfaceBasisResult basisOf(const SurfaceDec& dec, int velocity, int scalar) {
    return solveSurfaceBasis(dec, {{1, velocity}}, scalar, {});
}

/// l(l+1), 2l+1 times each, for the first `count` non-constant modes of the unit sphere.
std::vector<double> sphereSpectrum(int count) {
    std::vector<double> out;
    for (int l = 1; int(out.size()) < count; ++l)
        for (int m = 0; m < 2 * l + 1 && int(out.size()) < count; ++m) out.push_back(l * (l + 1.0));
    return out;
}

double maxAbs(const Eigen::MatrixXd& m) {
    return m.size() ? m.cwiseAbs().maxCoeff() : 0.0;
}

TEST(SurfaceDec, IncidencesComposeToZeroAndStarsAddUpToTheArea) {
    const TriangleMesh mesh = makeBlobMesh(2, 3);
    const SurfaceDec dec = decOf(mesh);
    EXPECT_EQ(maxAbs(Eigen::MatrixXd(dec.d1 * dec.d0)), 0.0);
    EXPECT_NEAR(dec.star0.sum(), dec.area.sum(), 1e-12 * dec.area.sum());
    // The cotan Laplacian annihilates constants.
    EXPECT_LT((dec.laplacian() * Eigen::VectorXd::Ones(dec.star0.size())).cwiseAbs().maxCoeff(),
              1e-12);
}

/// A flat triangular bipyramid: each equatorial edge faces two angles of almost 120°, so its
/// cotan weight is negative. The Laplacian stays positive semi-definite (it is the P1 stiffness
/// matrix), and on divergence-free fluxes ⋆1 is still exactly the L² energy of the face-wise
/// constant velocity, so energies stay positive.
TEST(SurfaceDec, NegativeCotanWeightsKeepTheEnergyExactAndPositive) {
    const double c = std::cos(2.0 * M_PI / 3.0), s = std::sin(2.0 * M_PI / 3.0);
    const TriangleMesh mesh{{{1, 0, 0}, {c, s, 0}, {c, -s, 0}, {0, 0, 0.1}, {0, 0, -0.1}},
                            {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}}};
    const SurfaceDec dec = decOf(mesh);
    std::cout << "smallest cotan weight " << dec.star1.minCoeff() << "\n";
    ASSERT_LT(dec.star1.minCoeff(), 0.0) << "the mesh was meant to have a negative weight";
    const Eigen::MatrixXd l = Eigen::MatrixXd(dec.laplacian());
    const Eigen::VectorXd spectrum =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(l).eigenvalues();
    EXPECT_GT(spectrum[0], -1e-12) << "the Laplacian lost its semi-definiteness";
    EXPECT_GT(spectrum[1], 1e-6) << "a second null vector appeared";

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd psi(5);
    for (auto& x : psi) x = uniform(rng);
    const Eigen::VectorXd flux = dec.d0 * psi;
    const FaceVelocityMap u = faceVelocityMap(dec, mesh);
    const Eigen::VectorXd u1 = u.alongE1 * flux, u2 = u.alongE2 * flux;
    double energy = 0.0;
    for (Eigen::Index t = 0; t < u1.size(); ++t)
        energy += dec.area[t] * (u1[t] * u1[t] + u2[t] * u2[t]);
    const double star = flux.dot(dec.star1.asDiagonal() * flux);
    EXPECT_NEAR(star, energy, 1e-12 * energy) << "Fᵀ⋆1F against Σ A|u|²";
    EXPECT_GT(star, 0.0);
}

TEST(SurfaceBasis, SphereSpectrumIsLTimesLPlusOneAndConvergesAtSecondOrder) {
    constexpr int kModes = 15;  // l = 1, 2, 3
    const std::vector<double> exact = sphereSpectrum(kModes);
    std::vector<double> errors;
    for (int level = 2; level <= 4; ++level) {
        const SurfaceDec dec = decOf(makeIcosphere(level));
        const SurfaceBasisResult basis = basisOf(dec, kModes, kModes);
        double error = 0.0;
        for (int m = 0; m < kModes; ++m) {
            error = std::max(error, std::abs(basis.scalarEigenvalues[m] - exact[std::size_t(m)]));
            EXPECT_DOUBLE_EQ(basis.velocityEigenvalues[m], basis.scalarEigenvalues[m])
                << "κ² = λ, mode " << m;
        }
        EXPECT_EQ(basis.harmonicCount, 0);
        std::cout << "icosphere " << level << ": max |λ − l(l+1)| = " << error << "\n";
        errors.push_back(error);
    }
    EXPECT_LT(errors[2], 0.05) << "the finest sphere's spectrum is off";
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log2(errors[i - 1] / errors[i]);
        EXPECT_GT(order, 1.9) << "convergence order between levels " << i + 1 << " and " << i + 2;
    }
    // Multiplicities 3, 5, 7: the gaps inside a degenerate group are far below those between.
    const SurfaceBasisResult fine = basisOf(decOf(makeIcosphere(4)), kModes, 0);
    const Eigen::VectorXd& k2 = fine.velocityEigenvalues;
    for (const auto& [first, last] : {std::pair{0, 2}, {3, 7}, {8, 14}}) {
        EXPECT_LT(k2[last] - k2[first], 0.01 * k2[first]) << "group " << first << "-" << last;
        if (last + 1 < k2.size()) {
            EXPECT_GT(k2[last + 1] - k2[last], 0.5 * k2[first]);
        }
    }
}

/// dim H¹ = dim ker d1 − rank d0, from the ranks of the incidences alone.
int firstBettiNumber(const SurfaceDec& dec) {
    const Eigen::MatrixXd d0 = Eigen::MatrixXd(dec.d0), d1 = Eigen::MatrixXd(dec.d1);
    const auto rank = [](const Eigen::MatrixXd& m) {
        return int(Eigen::FullPivLU<Eigen::MatrixXd>(m).rank());
    };
    return int(d1.cols()) - rank(d1) - rank(d0);
}

void expectHarmonic(const SurfaceDec& dec, const Eigen::MatrixXd& h) {
    const Eigen::MatrixXd gram = h.transpose() * dec.star1.asDiagonal() * h;
    EXPECT_LT(maxAbs(gram - Eigen::MatrixXd::Identity(h.cols(), h.cols())), 1e-12)
        << "⋆1-orthonormal";
    EXPECT_LT(maxAbs(dec.d1 * h) / maxAbs(h), 1e-14) << "divergence";
    EXPECT_LT(maxAbs(vertexVorticity(dec, h)), 1e-9) << "vorticity";
}

TEST(SurfaceBasis, TorusHasExactlyTwoHarmonicFields) {
    const TriangleMesh mesh = makeTorus(24, 12, 1.0, 0.45);
    const SurfaceDec dec = decOf(mesh);
    EXPECT_EQ(firstBettiNumber(dec), 2);
    const Eigen::MatrixXd h = harmonicForms(dec);
    ASSERT_EQ(h.cols(), 2);
    expectHarmonic(dec, h);
    // The Hodge Laplacian of 1-forms (every weight positive on this mesh) has exactly two zero
    // eigenvalues, and the harmonic fields are its null vectors.
    ASSERT_GT(dec.star1.minCoeff(), 0.0);
    const Eigen::MatrixXd s1 = dec.star1.asDiagonal();
    const Eigen::MatrixXd l1 =
        s1 * Eigen::MatrixXd(dec.d0) * dec.star0.cwiseInverse().asDiagonal() *
            Eigen::MatrixXd(dec.d0).transpose() * s1 +
        Eigen::MatrixXd(dec.d1).transpose() * dec.star2.asDiagonal() * Eigen::MatrixXd(dec.d1);
    const Eigen::VectorXd values =
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(l1, s1).eigenvalues();
    std::cout << "Hodge Laplacian: " << values[0] << ", " << values[1] << ", " << values[2] << "\n";
    EXPECT_LT(std::abs(values[1]), 1e-9);
    EXPECT_GT(values[2], 0.1);
    EXPECT_LT(maxAbs(l1 * h), 1e-9);
    const SurfaceBasisResult basis = basisOf(dec, 6, 0);
    EXPECT_EQ(basis.harmonicCount, 2);
    EXPECT_EQ(basis.velocityEigenvalues[1], 0.0);
    EXPECT_GT(basis.velocityEigenvalues[2], 0.1);
}

TEST(SurfaceBasis, GenusTwoSurfaceHasExactlyFourHarmonicFields) {
    const SurfaceDec dec = decOf(makeDoubleTorus(2));
    EXPECT_EQ(firstBettiNumber(dec), 4);
    const Eigen::MatrixXd h = harmonicForms(dec);
    ASSERT_EQ(h.cols(), 4);
    expectHarmonic(dec, h);
    EXPECT_EQ(harmonicForms(decOf(makeIcosphere(2))).cols(), 0);
}

TEST(SurfaceBasis, BasisIsOrthonormalAndDivergenceFreeToRoundOff) {
    const TriangleMesh mesh = makeBlobMesh(3, 1);
    const SurfaceDec dec = decOf(mesh);
    const SurfaceBasisResult basis = basisOf(dec, 40, 30);
    const Eigen::MatrixXd& v = basis.velocityModes;
    const double velocityError =
        maxAbs(v.transpose() * dec.star1.asDiagonal() * v - Eigen::MatrixXd::Identity(40, 40));
    const double scalarError =
        maxAbs(basis.scalarModes.transpose() * dec.star0.asDiagonal() * basis.scalarModes -
               Eigen::MatrixXd::Identity(30, 30));
    const double divergence = maxAbs(dec.d1 * v) / maxAbs(v);
    std::cout << "orthonormality " << velocityError << " (velocity), " << scalarError
              << " (scalar); divergence " << divergence << "\n";
    EXPECT_LT(velocityError, 1e-10);
    EXPECT_LT(scalarError, 1e-10);
    EXPECT_LT(divergence, 1e-14);
}

TEST(SurfaceBasis, RefusesMoreModesThanTheSurfaceHolds) {
    const SurfaceDec dec = decOf(makeIcosphere(0));  // 12 vertices: 11 co-exact fields
    EXPECT_THROW(basisOf(dec, 12, 0), Error);
    EXPECT_THROW(basisOf(dec, 4, 12), Error);
    EXPECT_EQ(basisOf(dec, 11, 11).velocityModes.cols(), 11);
}

/// C for ψ_i = z, ψ_k = x, ψ_j = y on the unit sphere: ω_i = Δz = −2z, (u_k × u_j)·n = z, so
/// C = −2∫z² dA = −8π/3.
TEST(SurfaceCoefficients, ConvergeAtSecondOrderToTheContinuumIntegral) {
    const double exact = -8.0 * M_PI / 3.0;
    std::vector<double> errors;
    for (int level = 2; level <= 5; ++level) {
        const TriangleMesh mesh = makeIcosphere(level);
        const SurfaceDec dec = decOf(mesh);
        Eigen::MatrixXd psi(dec.star0.size(), 3);  // columns k = x, j = y, i = z
        for (Eigen::Index v = 0; v < psi.rows(); ++v)
            for (int a = 0; a < 3; ++a) psi(v, a) = mesh.vertices[std::size_t(v)][std::size_t(a)];
        const std::vector<double> packed = assembleSurfaceCoefficients(dec, mesh, dec.d0 * psi);
        const double c = packed[packedIndex(3, 0, 2, 1)];
        EXPECT_DOUBLE_EQ(packed[packedIndex(3, 0, 2, 1)], c);
        errors.push_back(std::abs(c - exact));
        std::cout << "icosphere " << level << ": C = " << c << " (continuum " << exact << ")\n";
    }
    for (std::size_t i = 1; i < errors.size(); ++i)
        EXPECT_GT(std::log2(errors[i - 1] / errors[i]), 1.8)
            << "between levels " << i + 1 << " and " << i + 2;
}

}  // namespace
}  // namespace modeflow
