#pragma once
/// @file PrintableText.h
/// Text from an input file (a scene's key or value, a token of a mesh) quoted in a message:
/// control characters would reach the user's terminal as commands, and a megabyte-long value
/// would bury the message.

#include <cstddef>
#include <string>
#include <string_view>

namespace modeflow {

/// `text` with control characters and bytes that are not UTF-8 written as \xNN, cut after
/// `maxChars` characters (then "..." follows).
std::string printableText(std::string_view text, std::size_t maxChars = 40);

}  // namespace modeflow
