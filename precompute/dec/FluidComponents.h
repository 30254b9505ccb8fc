#pragma once
/// @file FluidComponents.h
/// The connected parts of a cut-cell domain's fluid: cells joined by a face DOF. Which part a
/// cell belongs to, and whether a part reaches an open side of the box (a face DOF with one
/// cell), where the pressure is held at 0: such a part has no constant pressure mode, and the
/// air may leave it.

#include <cstdint>
#include <vector>

#include "precompute/dec/CutCellDec.h"

namespace modeflow {

struct FluidComponents {
    /// Per cell DOF, the cell DOF that stands for its part (the same for every cell of it).
    std::vector<std::int64_t> of;
    /// Per cell DOF standing for a part: whether the part reaches an open side.
    std::vector<bool> open;

    /// The parts that reach no open side (each holds one constant pressure mode).
    int closedCount() const;
};

FluidComponents fluidComponents(const CutCellDec& dec);

}  // namespace modeflow
