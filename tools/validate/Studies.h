#pragma once
/// @file Studies.h
/// The studies of `modeflow validate`, one file each (allStudies() lists them in order).

#include "engine/core/SceneSpec.h"
#include "tools/validate/Study.h"

namespace modeflow::validate {

StudyResult convergenceStudy(const StudyOptions& options);
StudyResult integratorStudy(const StudyOptions& options);
StudyResult mhdStudy(const StudyOptions& options);
StudyResult coefficientStudy(const StudyOptions& options);
StudyResult resolutionStudy(const StudyOptions& options);
StudyResult speedStudy(const StudyOptions& options);
StudyResult reducedVsFullStudy(const StudyOptions& options);
StudyResult lansAlphaStudy(const StudyOptions& options);
StudyResult wakeStudy(const StudyOptions& options);

/// reduced_vs_full's periodic band-limited experiment (PeriodicReducedVsFull.cpp): its JSON.
nlohmann::json periodicBandLimited(const StudyOptions& options);

/// The vortex pair of scenes/seed/vortex_merge_2d.toml at `cells`², no dye, with every
/// divergence-free mode of that grid.
SceneSpec vortexPairWithAllModes(int cells, const StudyOptions& options);

}  // namespace modeflow::validate
