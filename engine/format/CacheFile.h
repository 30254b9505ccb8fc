#pragma once
/// @file CacheFile.h
/// The cache file: little-endian binary, versioned, checksummed, written atomically.
///
/// Layout: magic "MODEFLOW-BASIS\0\0" (16 bytes) | u32 format version | u32 reserved |
/// u64 key hash (FNV-1a) | u64 payload size | payload | u64 XXH3 checksum of the payload.
/// A file with another magic, version, size or checksum is refused, never misread.

#include <cstdint>
#include <filesystem>
#include <string_view>

#include "engine/core/BinaryCodec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// 3: periodic axes; 4: closed-form bases; 5: surface bases; 6: the vorticity quadrature of every
/// eigensolved grid basis and coefficient storage "none" (tensor-free advection); 7: XXH3
/// checksum.
inline constexpr std::uint32_t kCacheFormatVersion =
    10;  ///< 10: the wind base flows' Stokes corrections

/// Writes to a temporary file beside `path` (AtomicFile.h), then renames it over `path`, so
/// readers see the old file or the whole new one.
/// @throw Error naming the path when it cannot be written.
void writeCache(const std::filesystem::path& path, const BasisCache& cache);

/// Reads the header first: a file that is no cache, or larger than any cache (64 GiB), is
/// refused before its bulk is read; a well-formed file that describes no basis a precompute
/// writes (CacheConsistency.h) is refused too.
/// @throw Error saying why the file cannot be used (missing, not a regular file, truncated,
///        corrupt, other version).
BasisCache readCache(const std::filesystem::path& path);

/// Whether `bytes`, the first bytes of a file, begin with the cache's magic: the file is a cache
/// (whole or damaged; readCache says which) and nothing else.
bool hasCacheMagic(std::string_view bytes);

/// Reads only the header's key hash; @throw Error like readCache for a damaged header.
std::uint64_t readCacheKeyHash(const std::filesystem::path& path);

}  // namespace modeflow
