#pragma once
/// @file QuotedText.h
/// Text from a user's file, made safe for an error message: a binary or very long line must not
/// reach the terminal raw (control bytes can garble or reprogram it).

#include <cstddef>
#include <string>
#include <string_view>

namespace modeflow {

/// `text` with control characters (C0, DEL, C1) and bytes that are not valid UTF-8 written as
/// \xHH; printable text, accents and symbols included, is kept as is.
std::string printableText(std::string_view text);

/// `text` in double quotes, escaped as printableText and `"`, `\` as \" and \\, cut after
/// `maxBytes` input bytes with "..." after the closing quote.
std::string quotedText(std::string_view text, std::size_t maxBytes = 40);

}  // namespace modeflow
