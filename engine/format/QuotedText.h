#pragma once
/// @file QuotedText.h
/// Text from a user's file, quoted for an error message: a binary or very long line must not
/// reach the terminal raw (control bytes can garble or reprogram it).

#include <cstddef>
#include <string>
#include <string_view>

namespace modeflow {

/// `text` in double quotes, bytes outside printable ASCII (and `"`, `\`) written as \xHH, \" and
/// \\, cut after `maxBytes` input bytes with "..." after the closing quote.
std::string quotedText(std::string_view text, std::size_t maxBytes = 40);

}  // namespace modeflow
