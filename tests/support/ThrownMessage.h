#pragma once
/// @file ThrownMessage.h
/// What a call refuses with: the message of the modeflow::Error it throws, or "" when it returns.

#include <string>
#include <utility>

#include "engine/core/Error.h"

namespace modeflow::testing {

template <typename Call>
std::string thrownMessage(Call&& call) {
    try {
        std::forward<Call>(call)();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace modeflow::testing
