/// @file PrintableText.cpp

#include "engine/core/PrintableText.h"

namespace modeflow {
namespace {

/// The length of the UTF-8 sequence of a printable character at the start of `text`, or 0: a
/// lead byte and its continuation bytes, neither overlong nor a surrogate nor beyond U+10FFFF,
/// and not a C1 control (U+0080–U+009F).
std::size_t printableSequence(std::string_view text) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(0);
    if (lead >= 0x20 && lead < 0x7f) return 1;
    const std::size_t length = lead >= 0xc2 && lead <= 0xdf   ? 2
                               : lead >= 0xe0 && lead <= 0xef ? 3
                               : lead >= 0xf0 && lead <= 0xf4 ? 4
                                                              : 0;
    if (length == 0 || text.size() < length) return 0;
    char32_t code = lead & (0xff >> (length + 1));
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(i) & 0xc0) != 0x80) return 0;
        code = (code << 6) | (byte(i) & 0x3f);
    }
    constexpr char32_t kSmallest[] = {0, 0, 0xa0, 0x800, 0x10000};  // 2 bytes: C1 controls too
    const bool surrogate = code >= 0xd800 && code <= 0xdfff;
    return code >= kSmallest[length] && code <= 0x10ffff && !surrogate ? length : 0;
}

}  // namespace

std::string printableText(std::string_view text, std::size_t maxChars) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    std::size_t chars = 0;
    while (!text.empty()) {
        if (chars++ == maxChars) return out + "...";
        if (const std::size_t n = printableSequence(text)) {
            out.append(text.substr(0, n));
            text.remove_prefix(n);
            continue;
        }
        const auto b = static_cast<unsigned char>(text.front());
        out.append("\\x").push_back(kHex[b >> 4]);
        out.push_back(kHex[b & 15]);
        text.remove_prefix(1);
    }
    return out;
}

}  // namespace modeflow
