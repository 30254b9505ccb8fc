#pragma once
/// @file BasisCache.h
/// What a precompute produces and the runtime reads (precompute/README.md, "How the precompute
/// works", step 6): the grid, the degrees of freedom with their Hodge stars, and the eigenbases.
/// Plain values, no solver types.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/core/TriangleMesh.h"
#include "engine/format/SeparableModes.h"
#include "engine/format/SparseRows.h"

namespace modeflow {

/// A basis on a grid (cut-cell DEC) or on a closed triangle surface (precompute/surface).
enum class BasisKind { Grid, Surface };

struct BasisCache {
    /// Canonical text of every input that shapes the basis; its hash names the file.
    std::string key;
    BasisKind kind = BasisKind::Grid;
    GridSpec grid;  ///< grid bases only
    WallKind wall = WallKind::FreeSlip;
    BoundaryTreatment boundary = BoundaryTreatment::CutCell;

    std::vector<double> cellFraction;  ///< every grid cell's fraction inside Ω (x fastest)

    /// Surface bases: the mesh and its edges, (a, b) with a < b. There the velocity DOFs are the
    /// edges (`faces` numbers them 0, 1, …; the flux across a→b towards its left seen from
    /// outside, ⋆1 the cotan weights), the divergence lives on the triangles (`cells`, ⋆2 =
    /// 1/area) and the scalar DOFs are the vertices (⋆0 their barycentric areas).
    struct Surface {
        TriangleMesh mesh;
        std::vector<std::array<int, 2>> edges;
        /// Spectral dye advection (seed eq. 6.2): A_m,ij = ∫Φ_i (Ψ_m·∇Φ_j) for the scalar modes
        /// i < j (one row per pair, engine/core/PackedLayout.h's row order), one column per
        /// velocity mode m; A_m,ji = −A_m,ij.
        Eigen::MatrixXd advection;
        /// Each velocity mode's velocity at the vertices: rows 3v, 3v+1, 3v+2 are x, y, z.
        Eigen::MatrixXd vertexVelocity;
    } surface;

    /// Velocity degrees of freedom: faces (CubicalComplex numbering) and their ⋆(n-1).
    std::vector<std::int64_t> faces;
    Eigen::VectorXd faceStar;
    /// Cells carrying divergence, and their ⋆n.
    std::vector<std::int64_t> cells;
    Eigen::VectorXd cellStar;

    struct Velocity {
        BasisSource source = BasisSource::Eigensolve;
        Eigen::VectorXd eigenvalues;  ///< κ², ascending within each range
        /// faces × count, ⋆(n-1)-orthonormal fluxes. A closed-form basis stores `separable`
        /// instead and leaves this empty (runs go through its transforms, VelocityBasis.h).
        Eigen::MatrixXd modes;
        std::vector<SeparableMode> separable;  ///< closed form: one descriptor per mode
        std::vector<int> modeNumbers;          ///< 1-based index in the div-free spectrum
        int harmonic = 0;
        double penalty = 0.0;  ///< grad-div penalty used by the solve
    } velocity;

    struct Scalar {
        ScalarBoundary boundary = ScalarBoundary::Neumann;
        std::vector<std::int64_t> cells;  ///< scalar DOFs (Dirichlet: cells with centre inside)
        Eigen::VectorXd cellStar;
        BasisSource source = BasisSource::Eigensolve;
        Eigen::VectorXd eigenvalues;  ///< μ², ascending
        Eigen::MatrixXd modes;        ///< cells × count, ⋆n-orthonormal (as for velocity)
        std::vector<SeparableMode> separable;
        int omittedConstants = 0;
    } scalar;

    /// The quadrature of the structural coefficients
    /// (precompute/coefficients/CoefficientAssembly.h): one row per vorticity element e of positive
    /// weight w_e, one column per velocity DOF, the linear maps from face fluxes to w_e·ω(e) and to
    /// the velocity components u_b(e), u_c(e). Every eigensolved grid basis holds it: a tensor-free
    /// run evaluates the advection from it and the modes
    /// (engine/dynamics/TensorFreeCoefficients.h), and a tensor can be assembled from it later. A
    /// closed-form or surface basis has none (no rows): its coefficients are always stored.
    struct Quadrature {
        SparseRows curl, velocityB, velocityC;
    } quadrature;

    /// A wind's held flows around [[domain]] walls (precompute/solve/WindBaseFlows.h): entry
    /// 2a + 0 for a unit wind along +a, 2a + 1 along −a, the face-normal velocities on every grid
    /// face of its potential flow (0 on faces with no fluid; empty where the walls let no such
    /// wind through). Bases with [[domain]] shapes hold 2·dim; a whole box none (its flow is the
    /// constant wind).
    std::vector<std::vector<double>> windBase;
    /// Per held flow, one amplitude per velocity mode: c with B + Ψc its Stokes flow within the
    /// basis, what viscosity relaxes the disturbance toward (the wall's condition; ≈ 0 at
    /// free-slip walls). Empty where windBase is, entry by entry.
    std::vector<std::vector<double>> windStokes;

    /// Structural coefficients C[k][i][j] of the velocity modes (seed eq. 6.7), k < j only.
    struct Coefficients {
        /// None: not assembled (`[basis] coefficients = "tensor-free"`, or chosen by "auto").
        enum class Storage { Dense, Sparse, None };
        Storage storage = Storage::Dense;
        /// Dense: packed as in engine/core/PackedLayout.h (pair (k,j) by pair, i fastest).
        std::vector<double> packed;
        /// Sparse: the entries kept, as parallel arrays (k < j).
        std::vector<std::int32_t> k, i, j;
        std::vector<double> value;
        /// Fraction of the k < j half that is non-zero (|C| > 1e-12 max |C|).
        double density = 0.0;
    } coefficients;

    /// Stage name → seconds, in pipeline order.
    std::vector<std::pair<std::string, double>> timings;
};

}  // namespace modeflow
