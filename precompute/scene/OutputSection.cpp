/// @file OutputSection.cpp
/// `[output]`: how many frames, and simulation steps per frame.

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

OutputSpec readOutput(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kOutputKeys);
    OutputSpec output;
    output.frames = reader.readInt(s, "frames", output.frames, 1);
    output.stepsPerFrame = reader.readInt(s, "steps_per_frame", output.stepsPerFrame, 1);
    return output;
}

}  // namespace modeflow::scene
