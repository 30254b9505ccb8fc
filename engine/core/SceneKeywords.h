#pragma once
/// @file SceneKeywords.h
/// How a scene file spells each choice (keyword ↔ enum tables): what the scene loader accepts,
/// and what summaries, status lines and messages print so that they read like the file.

#include <span>
#include <string_view>
#include <utility>

#include "engine/core/SceneSpec.h"

namespace modeflow {
namespace keywords {

template <typename T>
using Choices = std::span<const std::pair<std::string_view, T>>;

inline constexpr std::pair<std::string_view, ShapeKind> kShapeKinds[] = {
    {"ball", ShapeKind::Ball},           {"box", ShapeKind::Box},
    {"ellipsoid", ShapeKind::Ellipsoid}, {"cylinder", ShapeKind::Cylinder},
    {"torus", ShapeKind::Torus},         {"mesh", ShapeKind::Mesh},
};
inline constexpr std::pair<std::string_view, CsgOp> kCsgOps[] = {
    {"union", CsgOp::Union}, {"subtract", CsgOp::Subtract}, {"intersect", CsgOp::Intersect}};
inline constexpr std::pair<std::string_view, ScalarBoundary> kScalarBoundaries[] = {
    {"neumann", ScalarBoundary::Neumann}, {"dirichlet", ScalarBoundary::Dirichlet}};
inline constexpr std::pair<std::string_view, WindProfile> kWindProfiles[] = {
    {"uniform", WindProfile::Uniform}, {"boundary-layer", WindProfile::BoundaryLayer}};
inline constexpr std::pair<std::string_view, WallKind> kWalls[] = {
    {"free-slip", WallKind::FreeSlip}, {"no-slip", WallKind::NoSlip}};
inline constexpr std::pair<std::string_view, BoundaryTreatment> kBoundaries[] = {
    {"cut-cell", BoundaryTreatment::CutCell}, {"staircase", BoundaryTreatment::Staircase}};
inline constexpr std::pair<std::string_view, CoefficientStorage> kCoefficientStorages[] = {
    {"auto", CoefficientStorage::Auto},
    {"dense", CoefficientStorage::Dense},
    {"sparse", CoefficientStorage::Sparse},
    {"tensor-free", CoefficientStorage::TensorFree}};
inline constexpr std::pair<std::string_view, EigensolverChoice> kEigensolvers[] = {
    {"auto", EigensolverChoice::Automatic},
    {"spectra", EigensolverChoice::Spectra},
    {"block", EigensolverChoice::Block},
    {"slepc", EigensolverChoice::Slepc}};
inline constexpr std::pair<std::string_view, Integrator> kIntegrators[] = {
    {"explicit", Integrator::Explicit},
    {"rk4", Integrator::Rk4},
    {"midpoint", Integrator::Midpoint},
    {"trapezoidal", Integrator::Trapezoidal},
    {"linearized", Integrator::Linearized}};
inline constexpr std::pair<std::string_view, InitialVelocity> kInitialVelocities[] = {
    {"zero", InitialVelocity::Zero},
    {"random", InitialVelocity::Random},
    {"modes", InitialVelocity::Modes},
    {"vortices", InitialVelocity::Vortices}};
inline constexpr std::pair<std::string_view, InitialMagnetic> kInitialMagnetics[] = {
    {"random", InitialMagnetic::Random}, {"uniform", InitialMagnetic::Uniform}};
inline constexpr std::pair<std::string_view, ObstacleShape> kObstacleShapes[] = {
    {"ball", ObstacleShape::Ball},
    {"box", ObstacleShape::Box},
    {"capsule", ObstacleShape::Capsule},
    {"mesh", ObstacleShape::Mesh}};
inline constexpr std::pair<std::string_view, AdvectionScheme> kAdvectionSchemes[] = {
    {"maccormack", AdvectionScheme::MacCormack},
    {"semi-lagrangian", AdvectionScheme::SemiLagrangian},
    {"conservative", AdvectionScheme::Conservative}};
inline constexpr std::pair<std::string_view, bool> kBasisPrecisions[] = {{"float32", false},
                                                                         {"float16", true}};
/// The grid box's sides by index 2·axis + (0 low, 1 high).
inline constexpr std::string_view kSideNames[] = {"x_min", "x_max", "y_min",
                                                  "y_max", "z_min", "z_max"};

template <typename T>
std::string_view keywordOf(Choices<T> choices, T value) {
    for (const auto& [name, v] : choices) {
        if (v == value) return name;
    }
    return "?";
}

}  // namespace keywords

/// The scene-file spelling of each choice ("ball", "subtract", "free-slip", "rk4", ...).
std::string_view sceneKeyword(ShapeKind kind);
std::string_view sceneKeyword(CsgOp op);
std::string_view sceneKeyword(ScalarBoundary boundary);
std::string_view sceneKeyword(WallKind wall);
std::string_view sceneKeyword(BoundaryTreatment treatment);
std::string_view sceneKeyword(CoefficientStorage storage);
std::string_view sceneKeyword(Integrator integrator);
std::string_view sceneKeyword(InitialVelocity velocity);
std::string_view sceneKeyword(AdvectionScheme scheme);

}  // namespace modeflow
