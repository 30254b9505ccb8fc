#pragma once
/// @file SmokeMaskFile.h
/// The smoke mask of a basis at a smoke scale, kept beside its cache file (HASH.smokeS.mfmask):
/// which cells of the smoke grid hold smoke. On a finer smoke grid that needs the domain itself
/// (whether each smoke cell's centre is inside Ω), which for mesh domains means rebuilding a level
/// set; the file keeps `run` and `stir` from doing so at every start.
///
/// Layout: magic "MODEFLOW-MASK\0\0\0" (16 bytes) | u32 version | u32 scale | u64 basis key hash |
/// u64 cell count | bit array (one bit per cell, cellIndex order, count-prefixed bytes) |
/// u64 XXH3 checksum (Checksum.h) of everything before it.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace modeflow {

/// Where the mask of the cache at `cachePath` is kept for smoke scale `scale`.
std::filesystem::path smokeMaskPath(const std::filesystem::path& cachePath, int scale);

/// Writes the mask (one byte per smoke cell, non-zero for smoke) atomically.
/// @throw modeflow::Error naming the file when it cannot be written.
void writeSmokeMask(const std::filesystem::path& path, std::uint64_t keyHash, int scale,
                    const std::vector<std::uint8_t>& mask);

/// The mask, one byte (0 or 1) per cell.
/// @throw modeflow::Error saying why the file cannot be used: missing, damaged, or made for
///        another basis, scale or cell count.
std::vector<std::uint8_t> readSmokeMask(const std::filesystem::path& path, std::uint64_t keyHash,
                                        int scale, std::size_t cells);

}  // namespace modeflow
