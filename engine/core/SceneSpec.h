#pragma once
/// @file SceneSpec.h
/// The validated content of a scene file (scenes/README.md, "Scene files"). Plain values only:
/// parsing and validation live in SceneLoader, so every other module can use a scene without
/// pulling in TOML.

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/GridSpec.h"

namespace modeflow {

enum class ShapeKind { Ball, Box, Ellipsoid, Cylinder, Torus, Mesh };
enum class CsgOp { Union, Subtract, Intersect };

/// One `[[domain]]` entry (or emitter shape). Unused fields keep their defaults.
struct ShapeSpec {
    ShapeKind kind = ShapeKind::Ball;
    Vec3 center{0.0, 0.0, 0.0};
    double radius = 0.0;             ///< ball, cylinder
    Vec3 radii{0.0, 0.0, 0.0};       ///< ellipsoid
    Vec3 min{0.0, 0.0, 0.0};         ///< box
    Vec3 max{0.0, 0.0, 0.0};         ///< box
    double halfHeight = 0.0;         ///< cylinder (axis z)
    double majorRadius = 0.0;        ///< torus (axis z)
    double minorRadius = 0.0;        ///< torus
    std::filesystem::path meshFile;  ///< mesh (OBJ, 3D), resolved against the scene's folder
    CsgOp op = CsgOp::Union;
    bool operator==(const ShapeSpec&) const = default;
};

enum class ScalarBoundary { Neumann, Dirichlet };
enum class WallKind { FreeSlip, NoSlip };
/// How primal measures see the domain: exact-for-piecewise-linear cut cells, or voxelized.
enum class BoundaryTreatment { CutCell, Staircase };
/// How the eigenbases are solved (precompute/solve): one shift-invert Lanczos run (Spectra), block
/// Lanczos around the same factorization, or spectrum slicing (SLEPc), or chosen by the mode count
/// and the number of MPI ranks. The bases are the same either way, so the choice is no part of the
/// cache key.
enum class EigensolverChoice { Automatic, Spectra, Block, Slepc };

/// How the runtime evaluates the advection Σ_ij C[k][i][j] v_i v_j: from a stored tensor (dense,
/// or sparse for bases where most entries vanish), or straight from the modes and the vorticity
/// quadrature without any tensor (tensor-free; engine/dynamics/TensorFreeCoefficients.h). Auto
/// lets the precompute choose by memory and cost (precompute/CoefficientChoice.h).
enum class CoefficientStorage { Auto, Dense, Sparse, TensorFree };

/// A 1-based, inclusive range of the divergence-free spectrum ("516-630").
struct ModeRange {
    int first = 1;
    int last = 1;
    bool operator==(const ModeRange&) const = default;
};

struct BasisSpec {
    std::vector<ModeRange> velocityModes;  ///< `velocity_modes = N` becomes {1-N}
    int scalarModes = 0;
    ScalarBoundary scalarBoundary = ScalarBoundary::Neumann;
    WallKind wall = WallKind::FreeSlip;
    BoundaryTreatment boundary = BoundaryTreatment::CutCell;
    int subsamples = 4;  ///< sub-cells per element edge when measuring cut fractions
    CoefficientStorage coefficients = CoefficientStorage::Auto;
    EigensolverChoice eigensolver = EigensolverChoice::Automatic;

    int velocityCount() const {
        int n = 0;
        for (const auto& r : velocityModes) n += r.last - r.first + 1;
        return n;
    }
    int highestVelocityMode() const {
        int n = 0;
        for (const auto& r : velocityModes) n = r.last > n ? r.last : n;
        return n;
    }
    bool operator==(const BasisSpec&) const = default;
};

/// The modal time integrators (engine/dynamics/ModalIntegrator.h has their equations).
enum class Integrator { Explicit, Rk4, Midpoint, Trapezoidal, Linearized };

/// Whether a step solves an equation (and reports iterations): all but explicit and rk4.
inline bool isImplicit(Integrator integrator) {
    return integrator != Integrator::Explicit && integrator != Integrator::Rk4;
}

struct SimulationSpec {
    double dt = 0.02;
    Integrator integrator = Integrator::Midpoint;
    double viscosity = 0.0;
    double alpha = 0.0;
    /// Ideal MHD (seed §6.3.5): a magnetic field in the velocity basis, advected by the flow and
    /// acting back on it through the Lorentz term.
    bool mhd = false;
    double magneticDiffusivity = 0.0;  ///< η: F_i decays as exp(−ηκ_i²t)
    /// Store the velocity basis in float16 on the device (half the memory and bandwidth of the
    /// reconstruction and force projection, ~1e-3 relative error in the grid velocity).
    bool halfPrecisionBasis = false;
};

enum class InitialVelocity { Zero, Random, Modes, Vortices };
/// The initial magnetic field of an MHD scene: random modal amplitudes, or a uniform field.
enum class InitialMagnetic { Random, Uniform };

/// One `[[initial.vortex]]`: a Gaussian-cored point vortex in 2D, a vortex ring in 3D.
struct VortexSpec {
    Vec3 center{0.0, 0.0, 0.0};
    double strength = 0.0;       ///< circulation Γ (counter-clockwise / right-handed about normal)
    double radius = 0.0;         ///< Gaussian core σ > 0
    Vec3 normal{0.0, 0.0, 1.0};  ///< 3D: the ring's axis (not normalized by the loader)
    double ringRadius = 0.0;     ///< 3D: radius of the ring's centre line
    bool operator==(const VortexSpec&) const = default;
};

struct InitialSpec {
    InitialVelocity velocity = InitialVelocity::Zero;
    /// random: ½|v|² of the result. vortices: rescale the projected state to it when > 0 (the
    /// loader leaves 0, "keep the projection's own energy", when the key is absent).
    double energy = 1.0;
    std::uint64_t seed = 1;
    /// random: the excited modes, 1-based inclusive positions in the basis; none means all.
    std::optional<ModeRange> band;
    /// modes: (1-based position in the basis, amplitude) pairs.
    std::vector<std::pair<int, double>> amplitudes;
    /// vortices: summed, then projected on the basis.
    std::vector<VortexSpec> vortices;
    /// MHD only: the initial magnetic field F in the velocity basis.
    InitialMagnetic magnetic = InitialMagnetic::Random;
    /// random: over all modes with this energy ½|F|², drawn with this seed.
    double magneticEnergy = 0.0;
    std::uint64_t magneticSeed = 2;
    /// uniform: |F| = magneticStrength along magneticDirection (not normalized by the loader,
    /// non-zero) away from the wall (precompute/initial/UniformField.h).
    Vec3 magneticDirection{1.0, 0.0, 0.0};
    double magneticStrength = 1.0;
    /// uniform: the width of the layer along the wall the field turns in; 0: one wavelength of
    /// the basis's highest mode (uniformFieldLayer).
    double magneticWallLayer = 0.0;
};

/// An obstacle's or a source's orientation at `time`: turned by `degrees` about `axis` (through its
/// centre) from the pose its shape keys describe.
struct RotationKey {
    double time = 0.0;
    Vec3 axis{0.0, 0.0, 1.0};  ///< unit length
    double degrees = 0.0;
};

/// A smoke/heat emitter (`[[source]]`): a ball, a box or a closed mesh (3D, world coordinates).
struct SourceSpec {
    ShapeSpec shape;
    double density = 1.0;      ///< injected per unit time
    double temperature = 0.0;  ///< injected per unit time
    double fuel = 0.0;         ///< injected per unit time; burns where `[fire]` says
    double start = 0.0;        ///< emits while start ≤ t < end (simulated seconds)
    double end = std::numeric_limits<double>::infinity();
    /// The emitted air's velocity (`velocity`): while the source emits, the fluid inside it is
    /// driven to move at it (a jet, a chimney's draught); none: the source adds smoke alone.
    std::optional<Vec3> velocity = std::nullopt;
    /// mesh: emit from the shell this thick inside its surface; 0: from its whole volume.
    double thickness = 0.0;
    /// Key frames moving it, as an obstacle's (`path`, `rotation`): its centre — a ball's centre,
    /// a box's middle, a mesh's origin — follows `path`, and it turns about that centre; empty:
    /// it stays where its shape keys put it.
    std::vector<std::pair<double, Vec3>> path;
    std::vector<RotationKey> rotation;
};

/// How smoke is carried (engine/README.md): RK2 semi-Lagrangian, MacCormack with clamping (less
/// diffusive; engine/reference/SmokeAdvection.h), or the flux form that keeps the smoke's mass
/// (engine/reference/ConservativeTransport.h; both backends).
enum class AdvectionScheme { SemiLagrangian, MacCormack, Conservative };

/// A solid moving through the fluid on a key-framed path (`[[obstacle]]`); the fluid's normal
/// velocity on the faces it covers is made to match its own (seed §6.3.5).
enum class ObstacleShape { Ball, Box, Capsule, Mesh };

struct ObstacleSpec {
    ObstacleShape shape = ObstacleShape::Ball;
    double radius = 0.0;           ///< ball, capsule
    Vec3 halfSize{0.0, 0.0, 0.0};  ///< box: half its extent per axis
    Vec3 axis{0.0, 0.0, 0.0};      ///< capsule: from its centre to one end of its segment
    /// mesh: a closed OBJ surface, resolved against the scene's folder; its origin is the
    /// obstacle's centre, its coordinates times `scale` are world lengths.
    std::filesystem::path meshFile;
    double scale = 1.0;  ///< mesh
    /// mesh: a deforming one's files per simulated second (`sequence_rate`): `meshFile` names a
    /// numbered sequence (MeshSequence.h), file k shown from (k − 1) / rate; 0: one rigid file.
    double sequenceRate = 0.0;
    /// Key frames (time, centre), times increasing; the centre moves linearly between them and
    /// holds still before the first and after the last.
    std::vector<std::pair<double, Vec3>> path;
    /// Key frames of its orientation, times increasing (MovingObstacle interpolates them); empty:
    /// it never turns.
    std::vector<RotationKey> rotation;
};

struct SmokeSpec {
    double buoyancy = 0.0;
    int resolutionScale = 1;
    AdvectionScheme advection = AdvectionScheme::MacCormack;
};

/// `[fire]`: fuel (a source's `fuel`) burns where the air is hotter than `ignition`, at
/// `burnRate` of what is there per unit time (first order: dF/dt = −burnRate·F), each unit burned
/// adding `heat` to the temperature and `smoke` to the density; the fuel burned per unit time is
/// the `flame` field (engine/simulation/Combustion.h).
struct FireSpec {
    double ignition = 1.0;
    double burnRate = 4.0;
    double heat = 2.0;
    double smoke = 0.5;
};

/// How a wind's speed changes with the height h over the floor (the box's low side along the up
/// axis): the same everywhere, or a boundary layer U (h / thickness)^exponent below `thickness`.
enum class WindProfile { Uniform, BoundaryLayer };

/// `[wind]`: the air far from solids moves at `velocity`, entering through the grid box's upstream
/// sides and leaving through its downstream ones (engine/README.md, "Wind"): a held base flow U
/// under the modes, u = U + Σ v_k Ψ_k. Grid scenes whose domain is the whole box.
struct WindSpec {
    Vec3 velocity{0.0, 0.0, 0.0};
    WindProfile profile = WindProfile::Uniform;
    double thickness = 0.0;       ///< boundary layer: where the wind reaches `velocity`
    double exponent = 1.0 / 7.0;  ///< boundary layer: of the power law (1/7: a turbulent one)
    /// What the air brings in through the upstream sides (0: clean, cool air).
    double density = 0.0;
    double temperature = 0.0;
    bool operator==(const WindSpec&) const = default;
};

/// `[[inflow]]`: air let in through part of a side the air crosses — an open side (`[grid] open`)
/// or a wind's upstream side (engine/README.md, "Inflows"). Where its ball or box meets the side,
/// the air coming in carries its `density`, `temperature` and `fuel` (elsewhere: clean air, or
/// the wind's); with a `velocity`, the air inside the shape is driven to it, as a jet source's.
struct InflowSpec {
    int side = 0;     ///< 2·axis + (0: the `_min` side, 1: the `_max` side)
    ShapeSpec shape;  ///< a ball or a box that meets the side's plane
    std::optional<Vec3> velocity = std::nullopt;
    double density = 0.0;  ///< concentrations of the air it lets in (0: clean, cool air)
    double temperature = 0.0;
    double fuel = 0.0;
    double start = 0.0;  ///< lets air in while start ≤ t < end (simulated seconds)
    double end = std::numeric_limits<double>::infinity();
};

/// `[forcing]`: velocity modes held at their initial amplitudes for the whole run. Held low modes
/// keep feeding energy to the others, the forcing of turbulence studies (seed §6.4, Fig. 6.9).
struct ForcingSpec {
    std::vector<ModeRange> holdModes;  ///< 1-based positions in the basis
    double holdBelowKappa = 0.0;       ///< every mode with κ below this (0: none)

    bool holds() const { return !holdModes.empty() || holdBelowKappa > 0.0; }
    bool operator==(const ForcingSpec&) const = default;
};

/// `[[particles]]`: points the air carries, seeded in a ball or a box (`shape`, with a source's
/// shape keys), either `count` of them at `start` or `rate` per simulated second from `start` until
/// `end` (at most until the shot's last step). With `drag` = 0 they are tracers moving at the
/// air's velocity; with `drag` > 0 inertial (a leaf, a spark): their velocity relaxes towards the
/// air's at that rate while `gravity` pulls them down the buoyancy axis.
struct ParticleSetSpec {
    ShapeSpec region;  ///< ball or box
    std::int64_t count = 0;
    double rate = 0.0;
    double start = 0.0;
    double end = std::numeric_limits<double>::infinity();
    double drag = 0.0;      ///< per unit time; 0: tracers
    double gravity = 9.81;  ///< inertial sets: acceleration down the buoyancy axis
    std::uint64_t seed = 1;
    bool operator==(const ParticleSetSpec&) const = default;
};

struct OutputSpec {
    int frames = 48;
    int stepsPerFrame = 1;
};

/// `[surface]`: the fluid lives on a closed triangle-mesh surface instead of in a grid's box
/// (scenes/README.md, "Curved surfaces").
struct SurfaceSpec {
    std::filesystem::path meshFile;  ///< OBJ, resolved against the scene's folder
    bool operator==(const SurfaceSpec&) const = default;
};

/// A whole scene, validated: every field holds a meaningful value.
struct SceneSpec {
    std::filesystem::path sourceFile;  ///< the TOML file it came from (empty if built in code)
    std::string name;                  ///< file stem, used to name outputs
    GridSpec grid;                     ///< grid scenes only
    std::vector<ShapeSpec> domain;     ///< empty: the whole grid box is fluid
    /// Set in a surface scene, which has no [grid] and no [[domain]] (`grid` keeps its defaults
    /// and means nothing there).
    std::optional<SurfaceSpec> surface;
    BasisSpec basis;
    SimulationSpec simulation;
    InitialSpec initial;
    std::vector<SourceSpec> sources;
    std::vector<ObstacleSpec> obstacles;
    std::vector<ParticleSetSpec> particles;
    SmokeSpec smoke;
    std::optional<FireSpec> fire;  ///< none: no `[fire]`, no fuel
    std::optional<WindSpec> wind;  ///< none: still air, sealed in the box
    std::vector<InflowSpec> inflows;
    ForcingSpec forcing;
    OutputSpec output;

    bool isSurface() const { return surface.has_value(); }
};

/// The scene's domain is the whole grid box (no [[domain]]): its bases have a closed form.
inline bool hasWholeBoxDomain(const SceneSpec& scene) {
    return scene.domain.empty();
}
/// The velocity basis comes in closed form: a whole box with free-slip walls (no-slip walls keep
/// the wall vorticity, whose eigenfields are not separable).
inline bool hasClosedFormVelocity(const SceneSpec& scene) {
    return hasWholeBoxDomain(scene) && scene.basis.wall == WallKind::FreeSlip &&
           !scene.grid.anyOpen();
}

}  // namespace modeflow
