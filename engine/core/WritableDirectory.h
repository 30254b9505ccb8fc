#pragma once
/// @file WritableDirectory.h
/// Output folders are created and probed for writing before any long work starts, so a bad path
/// fails in a second, not after minutes of solving or simulating.

#include <filesystem>
#include <string>

namespace modeflow {

/// Creates `dir` (and its parents) if needed and checks a file can be written in it.
/// @throw modeflow::Error "<what> <dir> cannot be created: ..." or "<what> <dir> is not writable",
/// followed by `hint` (e.g. which option chooses another folder).
void ensureWritableDirectory(const std::filesystem::path& dir, const std::string& what,
                             const std::string& hint);

/// Checks that `file` can be written later (a screenshot at the end of a session): it is no
/// folder, and its folder exists and takes a file. Creates nothing.
/// @throw modeflow::Error "<what> <file>: ..." saying which of these fails.
void requireWritableFile(const std::filesystem::path& file, const std::string& what);

}  // namespace modeflow
