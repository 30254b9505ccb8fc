/// @file OutputSection.cpp
/// `[output]`: how many frames, and simulation steps per frame.

#include <cstdint>
#include <limits>

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

OutputSpec readOutput(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kOutputKeys);
    OutputSpec output;
    output.frames = reader.readInt(s, "frames", output.frames, 1);
    output.stepsPerFrame = reader.readInt(s, "steps_per_frame", output.stepsPerFrame, 1);
    // The run's step count is an int.
    const std::int64_t steps = std::int64_t{output.frames} * output.stepsPerFrame;
    if (steps > std::numeric_limits<int>::max()) {
        reader.fail(s, "steps_per_frame",
                    "frames x steps_per_frame = " + std::to_string(steps) + " steps, more than " +
                        std::to_string(std::numeric_limits<int>::max()),
                    s.table.get("steps_per_frame") != nullptr ? s.table.get("steps_per_frame")
                                                              : s.table.get("frames"));
    }
    return output;
}

}  // namespace modeflow::scene
