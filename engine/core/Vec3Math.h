#pragma once
/// @file Vec3Math.h
/// The few operations on points and directions (Vec3, GridSpec.h) that geometry code needs:
/// mesh picking and cameras, surface topology, vortex and wall fields.

#include <cmath>

#include "engine/core/GridSpec.h"

namespace modeflow {

inline Vec3 sub(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

inline double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}

/// `a` scaled to length 1 (a zero vector stays NaN: callers pass non-zero directions).
inline Vec3 normalized(const Vec3& a) {
    const double n = norm(a);
    return {a[0] / n, a[1] / n, a[2] / n};
}

}  // namespace modeflow
