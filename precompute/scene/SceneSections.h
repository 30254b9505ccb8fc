#pragma once
/// @file SceneSections.h
/// Internal to precompute/scene: one reader per table of a scene file. Each checks its table's
/// keys before reading them and its values one by one; checks that involve several tables live
/// in SceneValidation.h.

#include <string>
#include <utility>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "precompute/scene/TomlReader.h"

namespace modeflow::scene {

/// `[grid]`; sets the reader's dimension, which every later vector has.
GridSpec readGrid(TomlReader& reader, const Section& s);

/// What a shape read by readShape is for: a `[[domain]]` entry (any shape, combined by `op`), a
/// `[[source]]` (a ball, box or mesh) or a `[[particles]]` set's seeding region (a ball or box);
/// the entry's other keys are the source's or the set's.
enum class ShapeUse { Domain, Source, Particles, Inflow };

/// The shape of one entry of `section` ("[[domain]]", "[[source]]" or "[[particles]]"), `index`
/// 1-based.
ShapeSpec readShape(const TomlReader& reader, const toml::table& table, const std::string& section,
                    int index, ShapeUse use);

/// "[[source]] #2 (ball)": how messages name entry `index` (1-based) of `section`, of that shape.
std::string shapeEntryName(const std::string& section, int index, ShapeKind kind);

/// An OBJ file named by `key` of `s`: resolved against the scene's folder, a regular file.
std::filesystem::path readMeshFile(const TomlReader& reader, const Section& s, std::string_view key,
                                   bool sequence = false);

/// `[surface]` (a surface scene); sets the reader's dimension to 3.
SurfaceSpec readSurface(TomlReader& reader, const Section& s);

/// A surface scene holds no [grid], [[domain]], [[obstacle]] or [smoke].
void checkSurfaceSceneTables(const TomlReader& reader, const toml::table& root);
/// `[basis]` (`s`) of a surface scene: no grid-only keys (wall, boundary, ...).
void checkSurfaceBasis(const TomlReader& reader, const Section& s);
/// `[simulation]` (`s`) of a surface scene: no MHD.
void checkSurfaceSimulation(const TomlReader& reader, const Section& s,
                            const SimulationSpec& simulation);
/// `[initial]` (`s`) of a surface scene: no vortices (they are projected on a grid).
void checkSurfaceInitial(const TomlReader& reader, const Section& s);

BasisSpec readBasis(const TomlReader& reader, const Section& s);
SimulationSpec readSimulation(const TomlReader& reader, const Section& s);

/// `[initial]`, including its magnetic field keys (the caller checks they belong to an MHD
/// scene).
InitialSpec readInitial(const TomlReader& reader, const Section& s);
/// `[[initial.vortex]]` entries of `[initial]` (`s`), at least one.
std::vector<VortexSpec> readVortices(const TomlReader& reader, const Section& s);

/// `path = [[t, x, y(, z)], ...]` of `s`: times increasing; empty when absent and not
/// `required`.
std::vector<std::pair<double, Vec3>> readPath(const TomlReader& reader, const Section& s,
                                              bool required);
/// `rotation = [[t, ax, ay, az, degrees], ...]` of `s`: times increasing, axes of non-zero length
/// (normalized here), about z alone in 2D; empty when absent.
std::vector<RotationKey> readRotation(const TomlReader& reader, const Section& s);

SourceSpec readSource(const TomlReader& reader, const toml::table& table, int index);
/// One `[[particles]]` set; `shotEnd` (the last step's end, frames x steps_per_frame x dt) bounds
/// the particles a `rate` emits, which at most maxParticles may be (`emitted` holds those of the
/// sets before it, and gains this one's).
ParticleSetSpec readParticleSet(const TomlReader& reader, const toml::table& table, int index,
                                double shotEnd, std::int64_t& emitted);
ObstacleSpec readObstacle(const TomlReader& reader, const Section& s);
/// A smoke value (density, temperature, fuel, heat) as readNumber reads it, at most kMaxSmokeValue
/// in magnitude.
double readSmokeValue(const TomlReader& reader, const Section& s, std::string_view key,
                      double fallback, Sign sign = Sign::Any);
SmokeSpec readSmoke(const TomlReader& reader, const Section& s);
FireSpec readFire(const TomlReader& reader, const Section& s);
/// One `[[inflow]]` of a grid scene (`scene` read up to [wind]: its sides and wind).
InflowSpec readInflow(const TomlReader& reader, const toml::table& table, int index,
                      const SceneSpec& scene);
/// `[wind]` of a grid scene whose domain is the whole box (`scene` read up to [fire]).
WindSpec readWind(const TomlReader& reader, const Section& s, const SceneSpec& scene);
ForcingSpec readForcing(const TomlReader& reader, const Section& s);
OutputSpec readOutput(const TomlReader& reader, const Section& s);

}  // namespace modeflow::scene
