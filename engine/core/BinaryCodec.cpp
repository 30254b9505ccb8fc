#include "engine/core/BinaryCodec.h"

#include <algorithm>

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

void ByteReader::read(void* to, std::size_t n) {
    if (n > remaining()) fail("truncated");
    if (n == 0) return;
    char* bytes = static_cast<char*>(to);
    if (mStream == nullptr) {
        std::memcpy(bytes, mBytes.data() + mAt, n);
    } else if (!mStream->read(bytes, std::streamsize(n))) {
        fail("unreadable to its end (it changed while it was read?)");
    }
    mAt += n;
    mChecksum.update({bytes, n});
}

void ByteReader::skip(std::size_t n) {
    char buffer[256];
    while (n > 0) {
        const std::size_t step = std::min(n, sizeof buffer);
        read(buffer, step);
        n -= step;
    }
}

void ByteReader::fail(std::string_view why) const {
    throw Error(mDescribe(why));
}

}  // namespace modeflow
