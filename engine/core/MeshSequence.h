#pragma once
/// @file MeshSequence.h
/// Numbered mesh files (`file = "flag_####.obj"`): the last run of '#' in the file name stands
/// for the 1-based file number, zero-padded to the run's width.

#include <filesystem>

namespace modeflow {

/// Whether `pattern`'s file name holds a '#'.
bool isMeshSequence(const std::filesystem::path& pattern);

/// File `number` of the sequence (`pattern` itself when it is no sequence).
std::filesystem::path sequenceFile(const std::filesystem::path& pattern, int number);

/// How many files, from number 1 on, follow one another on the disk (at most `limit`).
int sequenceLength(const std::filesystem::path& pattern, int limit);

}  // namespace modeflow
