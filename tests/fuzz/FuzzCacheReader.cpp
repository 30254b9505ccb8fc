/// Fuzz target: the cache reader. Inputs with the cache magic are whole files (the header's
/// checks); others are payloads, given a valid header and checksum so that the decoder and the
/// consistency checks see them (no fuzzer finds a 64-bit checksum by chance).

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"
#include "engine/format/CacheFile.h"
#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {
namespace {

/// The hash of the key a payload begins with (u64 length, bytes), as the header must hold it.
std::uint64_t keyHash(std::string_view payload) {
    try {
        return fnv1a64(
            ByteReader(payload, [](std::string_view why) { return std::string(why); }).string());
    } catch (const Error&) {
        return 0;  // no whole key: the reader refuses the payload before it compares hashes
    }
}

/// A cache file around `payload` (layout in CacheFile.h).
std::string cacheFileAround(std::string_view payload) {
    ByteWriter file;
    file.values("MODEFLOW-BASIS\0\0", 16);
    file.pod(kCacheFormatVersion);
    file.pod(std::uint32_t{0});
    file.pod(keyHash(payload));
    file.pod(std::uint64_t(payload.size()));
    file.values(payload.data(), payload.size());
    file.pod(checksum64(payload));
    return file.bytes();
}

std::string bytesOf(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

bool cacheReader(std::string_view bytes) {
    const auto input = scratchFile(
        "input.mfbasis", hasCacheMagic(bytes) ? std::string(bytes) : cacheFileAround(bytes));
    BasisCache cache;
    if (!acceptedOrRefused([&] { cache = readCache(input); })) return false;
    require(readCacheKeyHash(input) == fnv1a64(cache.key),
            "readCacheKeyHash disagrees with readCache");
    // What was accepted is written and read back to the same bytes (values compared as bytes:
    // a NaN in the file is not the reader's business).
    const auto first = input.parent_path() / "first.mfbasis",
               second = input.parent_path() / "second.mfbasis";
    writeCache(first, cache);
    writeCache(second, readCache(first));
    require(bytesOf(first) == bytesOf(second),
            "an accepted cache does not survive a write and a read");
    return true;
}

}  // namespace modeflow::fuzz
