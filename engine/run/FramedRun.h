#pragma once
/// @file FramedRun.h
/// A simulation whose frames a run writes, as FrameLoop drives it: a grid scene's (GridFrames:
/// OpenVDB files) or a surface scene's (SurfaceFrames: PLY files).

#include <cstdint>
#include <filesystem>

#include "engine/run/FrameProgress.h"
#include "engine/simulation/Checkpoint.h"
#include "engine/simulation/FrameStats.h"
#include "engine/simulation/SimulationSettings.h"

namespace modeflow {

class FramedRun {
public:
    virtual ~FramedRun() = default;

    virtual const SimulationSettings& settings() const = 0;
    virtual double time() const = 0;
    /// Advances one frame (settings().stepsPerFrame steps).
    /// @throw ModalStateDiverged when the modal state stops being finite.
    virtual FrameStats advanceFrame() = 0;
    /// Where frame `frame` is written; its picture has the same name ending in .png.
    virtual std::filesystem::path frameFile(int frame) const = 0;
    /// Writes frame `frame` (and its picture to `picture` unless empty), timing each part on
    /// `bar`, and returns the state to resume from after it (its runHash left to the caller).
    virtual Checkpoint writeFrame(int frame, const std::filesystem::path& picture,
                                  FrameProgress& bar) = 0;
    /// Continues from a checkpoint this kind of run wrote.
    virtual void restore(const Checkpoint& from) = 0;
};

}  // namespace modeflow
