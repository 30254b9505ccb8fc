#pragma once
/// @file Checksum.h
/// The checksum of modeflow's files (basis caches, checkpoints, smoke masks, eigensolver slices):
/// XXH3's 64-bit hash (libxxhash), one call or streamed. It replaced FNV-1a over the bytes, which
/// goes a byte a step, several times slower (precompute/README.md "How the precompute works",
/// cache). FNV-1a (BinaryCodec.h) still names caches by their short keys.

#include <cstdint>
#include <string_view>

#define XXH_STATIC_LINKING_ONLY  // XXH3_state_t by value: no allocation per reader
#include <xxhash.h>

namespace modeflow {

/// XXH3-64 of `bytes` (seed 0).
std::uint64_t checksum64(std::string_view bytes);

/// The same over bytes that come in pieces: update() with each in order, then value().
class Checksum {
public:
    Checksum();
    void update(std::string_view bytes);
    std::uint64_t value() const;

private:
    XXH3_state_t mState;
};

}  // namespace modeflow
