#pragma once
/// @file SceneValidation.h
/// Internal to precompute/scene: the checks that involve more than one table (a basis that fits
/// the grid, initial modes inside the basis, 2D/3D consistency, ...) or the runtime's limits
/// (engine/core/RuntimeLimits.h). Each is called as soon as the tables it needs are read, so a
/// file's first mistake is the one reported.

#include "engine/core/SceneSpec.h"
#include "precompute/scene/TomlReader.h"

namespace modeflow::scene {

/// Cylinders, tori and meshes are 3D only; the reader's dimension is the grid's.
void checkShapeDimension(const TomlReader& reader, const Section& shape, ShapeKind kind,
                         const toml::node* shapeNode);

/// The highest velocity mode and the scalar mode count of `[basis]` (`s`) within what the grid's
/// faces and cells can hold.
void checkBasisFitsGrid(const TomlReader& reader, const Section& s, const BasisSpec& basis,
                        const GridSpec& grid);

/// Magnetic field keys in `[initial]` (`s`) only when `[simulation]` has mhd = true.
void checkInitialFieldKeys(const TomlReader& reader, const Section& s,
                           const SimulationSpec& simulation);

/// The band and the modal amplitudes of `[initial]` (`s`) inside the basis.
void checkInitialFitsBasis(const TomlReader& reader, const Section& s, const InitialSpec& initial,
                           const BasisSpec& basis);

/// The speeds `[initial]` (`s`) sets within kMaxInitialSpeed, measured on the grid's box.
void checkInitialSpeeds(const TomlReader& reader, const Section& s, const InitialSpec& initial,
                        const GridSpec& grid);

/// The held modes of `[forcing]` (`s`) inside the basis, and no `[forcing]` with MHD.
void checkForcingFitsScene(const TomlReader& reader, const Section& s, const ForcingSpec& forcing,
                           const BasisSpec& basis, const SimulationSpec& simulation);

/// The smoke grid (the grid refined by `[smoke]` resolution_scale) within kMaxSmokeCells.
void checkSmokeGridSize(const TomlReader& reader, const Section& s, const SmokeSpec& smoke,
                        const GridSpec& grid);

/// At most `limit` `[[name]]` entries (`what` names them in the message, "sources").
void checkEntryCount(const TomlReader& reader, const toml::table& root, std::string_view name,
                     int limit, std::string_view what);

}  // namespace modeflow::scene
