#include "engine/format/QuotedText.h"

namespace modeflow {
namespace {

/// The length of the valid, printable UTF-8 sequence at the start of `text` (0 if none): a
/// lead byte, its continuation bytes, no overlong forms, surrogates or C1 controls.
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
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(k) & 0xc0) != 0x80) return 0;
        code = (code << 6) | (byte(k) & 0x3f);
    }
    const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    const bool valid =
        code >= smallest[length] && code <= 0x10ffff && !(code >= 0xd800 && code <= 0xdfff);
    return valid && !(code >= 0x80 && code <= 0x9f) ? length : 0;
}

/// `text` escaped as printableText, with `"` and `\` escaped too if `quoted`.
std::string escaped(std::string_view text, bool quoted) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    while (!text.empty()) {
        const unsigned char c = static_cast<unsigned char>(text[0]);
        std::size_t length = printableSequence(text);
        if (quoted && (c == '"' || c == '\\')) {
            out += '\\';
            out += char(c);
        } else if (length > 0) {
            out.append(text.substr(0, length));
        } else {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 0xf];
            length = 1;
        }
        text.remove_prefix(length);
    }
    return out;
}

}  // namespace

std::string printableText(std::string_view text) {
    return escaped(text, false);
}

std::string quotedText(std::string_view text, std::size_t maxBytes) {
    std::string quoted(1, '"');
    quoted += escaped(text.substr(0, maxBytes), true);
    quoted += '"';
    if (text.size() > maxBytes) quoted += "...";
    return quoted;
}

}  // namespace modeflow
