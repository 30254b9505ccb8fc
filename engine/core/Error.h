#pragma once
/// @file Error.h
/// The one exception type modeflow's libraries throw. The message says what failed and why, in
/// words a user can act on (it names the scene key, file or stage); the CLI prints it as is.

#include <stdexcept>
#include <string>

namespace modeflow {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace modeflow
