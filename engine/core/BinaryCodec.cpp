#include "engine/core/BinaryCodec.h"

#include "engine/core/Error.h"

namespace modeflow {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed) {
    std::uint64_t h = seed;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

void ByteReader::fail(std::string_view why) const {
    throw Error(mDescribe(why));
}

}  // namespace modeflow
