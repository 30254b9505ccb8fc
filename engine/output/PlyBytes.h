#pragma once
/// @file PlyBytes.h
/// Internal to engine/output: a binary little-endian PLY body, value by value.

#include <cstring>
#include <string>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "PLY frames are written little-endian");

namespace modeflow::ply {

template <typename T>
void put(std::string& bytes, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
}

}  // namespace modeflow::ply
