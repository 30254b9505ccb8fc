#include "engine/core/Checksum.h"

namespace modeflow {

std::uint64_t checksum64(std::string_view bytes) {
    return XXH3_64bits(bytes.data(), bytes.size());
}

Checksum::Checksum() {
    XXH3_INITSTATE(&mState);
    XXH3_64bits_reset(&mState);
}

void Checksum::update(std::string_view bytes) {
    XXH3_64bits_update(&mState, bytes.data(), bytes.size());
}

std::uint64_t Checksum::value() const {
    return XXH3_64bits_digest(&mState);
}

}  // namespace modeflow
