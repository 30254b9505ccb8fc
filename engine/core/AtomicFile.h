#pragma once
/// @file AtomicFile.h
/// Files that are never seen half-written: each is written under a temporary name beside its
/// final one (NAME.tmp-PID) and renamed over it only when complete, so a reader, a killed run or
/// a full disk leaves either the old file or the whole new one, and never a partial file under
/// a final name. Temporaries of processes that no longer run can be swept away.

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <span>
#include <string_view>

namespace modeflow {

/// `path` with ".tmp-PID" appended, PID this process's.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

/// Writes `bytes` as the whole content of `path`.
/// @throw modeflow::Error "cannot write <what> <path>: <the system's reason>" (e.g. "No space
///        left on device"); the temporary file is removed and an existing `path` left as it was.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes,
                         std::string_view what);

/// The same for a file made of `pieces` one after another (a header, a large payload, a
/// checksum), written without joining them in memory first.
void writeFileAtomically(const std::filesystem::path& path,
                         std::initializer_list<std::string_view> pieces, std::string_view what);
/// The same for pieces counted at run time (a cache's records and arrays).
void writeFileAtomically(const std::filesystem::path& path,
                         std::span<const std::string_view> pieces, std::string_view what);

/// The same for writers that need a file name (OpenVDB, image encoders): `write` writes the
/// temporary file it is given, then it is renamed over `path`. Whatever `write` throws is
/// rethrown after the temporary is removed.
void writeFileAtomically(const std::filesystem::path& path, std::string_view what,
                         const std::function<void(const std::filesystem::path& temporary)>& write);

/// Removes the temporaries (NAME.tmp-PID) in `folder` whose process no longer runs, left by
/// killed runs; returns how many it removed. Missing folders and unremovable files are skipped.
int removeStaleTemporaries(const std::filesystem::path& folder);

}  // namespace modeflow
