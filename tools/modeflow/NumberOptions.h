#pragma once
/// @file NumberOptions.h
/// The checks of every numeric command-line option, so that each refuses what makes no sense
/// (nan, inf, 0 frames, a billion-pixel window) with one short message naming the option:
/// "--dt: must be a finite number greater than 0, got "nan"".

#include <CLI/CLI.hpp>

namespace modeflow::cli {

/// The most frames a run or a stir session may ask for.
inline constexpr long long kMaxFrames = 1'000'000;
/// The most steps `modeflow modes` may take.
inline constexpr long long kMaxSteps = 1'000'000'000;

/// A finite number greater than 0.
CLI::Validator finitePositive();
/// A finite number greater than or equal to 0.
CLI::Validator finiteNonNegative();
/// A whole number from 1 to `maximum`.
CLI::Validator countUpTo(long long maximum);

}  // namespace modeflow::cli
