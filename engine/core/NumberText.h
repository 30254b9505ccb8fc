#pragma once
/// @file NumberText.h
/// Numbers in error messages: a few significant digits, so that 1e300 reads "1e+300", never as
/// 309 digits.

#include <cstdio>
#include <string>

namespace modeflow {

inline std::string numberText(double x, int digits = 3) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    return buffer;
}

}  // namespace modeflow
