#pragma once
/// @file Precompute.h
/// Scene → cut-cell DEC → eigenbases → cache file (precompute/README.md, "How the precompute
/// works"). The only entry point the command line needs; every stage below it is a separate module.

#include <filesystem>
#include <string>

#include "engine/core/Progress.h"
#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// Canonical text of everything that shapes the basis: grid, domain (mesh files by content),
/// basis settings, cache format and algorithm versions. Equal keys ⇔ interchangeable caches.
/// @throw Error when a mesh file cannot be read.
std::string basisKey(const SceneSpec& scene);

/// `DIR/<16 hex digits of the key's hash>.mfbasis`, for a key from basisKey().
std::filesystem::path cachePath(const std::string& key, const std::filesystem::path& cacheDir);

/// How the bases are found: in closed form where the domain allows it (a whole box with
/// free-slip walls: precompute/closedform), else by the eigensolver; or always by the eigensolver
/// (to compare the two).
enum class BasisMethod { Automatic, Eigensolve };

/// Runs the whole pipeline in memory, after checking its estimated peak memory against the
/// machine's (precompute/PrecomputeMemory.h).
/// @throw Error naming the scene key or stage that failed, "out of memory in <stage>" included.
BasisCache computeBasis(const SceneSpec& scene, Progress& progress,
                        BasisMethod method = BasisMethod::Automatic);

struct CacheOutcome {
    std::filesystem::path path;
    bool reused = false;  ///< a valid cache with the same key was already there
    BasisCache cache;     ///< its content (read to check it, or just computed)
};

/// Returns the scene's cache, computing and writing it on a miss, or always when `force`.
/// The cache folder is created and checked for writing before any work starts. A damaged or
/// stale file under the scene's name is reported on the progress stream and rebuilt. Sliced
/// eigensolves keep their finished intervals beside the cache until it is written, and resume
/// from those an interrupted run kept (precompute/solve/SliceCheckpoint.h); `force` discards them.
/// Under mpirun (precompute/solve/ProcessGroup.h) every rank takes part in the eigensolves and
/// rank 0 alone assembles the coefficients and writes the file: the other ranks' outcome holds
/// the path and the bases only.
CacheOutcome ensureCache(const SceneSpec& scene, const std::filesystem::path& cacheDir, bool force,
                         Progress& progress);

}  // namespace modeflow
