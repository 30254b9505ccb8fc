#pragma once
/// @file StepRecording.h
/// How a device simulation records its steps: once per configuration and resubmitted
/// (vulkan::CommandSequence::keepNextRecording), or afresh every step (for comparisons).

namespace modeflow::device {

enum class StepRecording { Once, EveryStep };

}  // namespace modeflow::device
