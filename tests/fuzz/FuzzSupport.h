#pragma once
/// @file FuzzSupport.h
/// What every fuzz target shares: the rule for refusals (a modeflow::Error with a printable
/// message), findings as an exception that no reader throws, and a scratch file for readers that
/// take a path.

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace modeflow::fuzz {

/// A reader broke a promise (a refusal message with raw bytes, a round trip that changed the
/// data). Thrown, never caught by the targets: libFuzzer reports it as a crash.
class FuzzFinding : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

/// @throw FuzzFinding unless `condition` holds.
void require(bool condition, const std::string& what);

/// Runs `read`; a modeflow::Error is an accepted refusal when its message is non-empty, at most
/// 4 KiB, and printable (printableText leaves it as it is: valid UTF-8, no control characters,
/// newlines included). Anything else propagates.
/// Returns whether `read` finished without refusing.
bool acceptedOrRefused(const std::function<void()>& read);

/// The message of the last refusal acceptedOrRefused saw in this process.
const std::string& lastRefusal();

/// `bytes` written to a file named `name` in this process's scratch folder (created once under
/// the temporary folder, removed at exit), whose path is returned.
std::filesystem::path scratchFile(const std::string& name, std::string_view bytes);

}  // namespace modeflow::fuzz
