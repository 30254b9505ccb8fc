#pragma once
/// @file HalfFloat.h
/// IEEE 754 binary16 conversions on the host, for data the shaders read with unpackHalf2x16
/// (two halves per 32-bit word, the lower-addressed value in the low 16 bits). Portable C++20
/// (no F16C, so generic x86-64 builds work too).

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace modeflow::device {

/// The nearest binary16 (ties to even), subnormals included; overflow gives ±infinity.
inline std::uint16_t floatToHalf(float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    const auto sign = std::uint16_t((bits >> 16) & 0x8000u);
    const std::uint32_t magnitude = bits & 0x7fffffffu;
    if (magnitude >= 0x7f800000u)
        return std::uint16_t(sign | 0x7c00u | (magnitude > 0x7f800000u ? 0x200u : 0u));
    if (magnitude >= 0x477ff000u) return std::uint16_t(sign | 0x7c00u);  // rounds beyond 65504
    if (magnitude < 0x38800000u) {
        // Below 2^-14: a subnormal half, i.e. a multiple of 2^-24; the scaling is exact and
        // nearbyint rounds ties to even.
        const float units = std::bit_cast<float>(magnitude) * 16777216.0f;
        return std::uint16_t(sign | std::uint16_t(std::nearbyint(units)));
    }
    std::uint32_t half = (magnitude - 0x38000000u) >> 13;  // rebias 127 → 15, keep 10 mantissa bits
    const std::uint32_t rest = magnitude & 0x1fffu;
    if (rest > 0x1000u || (rest == 0x1000u && (half & 1u)))
        ++half;  // a carry moves into the exponent
    return std::uint16_t(sign | half);
}

inline float halfToFloat(std::uint16_t half) {
    const float sign = (half & 0x8000u) ? -1.0f : 1.0f;
    const int exponent = (half >> 10) & 0x1f;
    const int mantissa = half & 0x3ff;
    if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
    if (exponent == 31)
        return mantissa ? std::numeric_limits<float>::quiet_NaN()
                        : sign * std::numeric_limits<float>::infinity();
    return sign * std::ldexp(float(mantissa | 0x400), exponent - 25);
}

}  // namespace modeflow::device
