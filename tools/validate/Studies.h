#pragma once
/// @file Studies.h
/// The studies of `modeflow validate`, one file each (allStudies() lists them in order).

#include "tools/validate/Study.h"

namespace modeflow::validate {

StudyResult convergenceStudy(const StudyOptions& options);
StudyResult integratorStudy(const StudyOptions& options);
StudyResult mhdStudy(const StudyOptions& options);

}  // namespace modeflow::validate
