#pragma once
/// @file FramedRun.h
/// A simulation whose frames a run writes, as FrameLoop drives it: a grid scene's (GridFrames:
/// OpenVDB files) or a surface scene's (SurfaceFrames: PLY files).

#include <cstdint>
#include <filesystem>
#include <functional>

#include "engine/run/FrameProgress.h"
#include "engine/simulation/Checkpoint.h"
#include "engine/simulation/FrameStats.h"
#include "engine/simulation/SimulationSettings.h"

namespace modeflow {

/// A frame read back from a run: the state to resume from after it, and the writing of its files,
/// which holds everything it needs and touches neither the simulation nor its device, so that it
/// may run on another thread while the run steps on (FrameLoop).
struct FrameOutput {
    Checkpoint checkpoint;  ///< its runHash left to the caller
    /// Writes the frame's files from `checkpoint` (this output's) and what it holds, timing each
    /// part on `bar` (whose timing may be called from any thread).
    std::function<void(const Checkpoint& checkpoint, FrameProgress& bar)> writeFiles;
};

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
    /// Reads frame `frame` back (and writes its picture to `picture` unless empty: a picture may
    /// need the device), timing each part on `bar`: its state and the writing of its files.
    virtual FrameOutput readFrame(int frame, const std::filesystem::path& picture,
                                  FrameProgress& bar) = 0;
    /// Continues from a checkpoint this kind of run wrote.
    virtual void restore(const Checkpoint& from) = 0;
};

}  // namespace modeflow
