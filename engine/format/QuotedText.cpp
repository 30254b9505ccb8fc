#include "engine/format/QuotedText.h"

namespace modeflow {

std::string quotedText(std::string_view text, std::size_t maxBytes) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string quoted = "\"";
    for (const unsigned char c : text.substr(0, maxBytes)) {
        if (c == '"' || c == '\\') {
            quoted += '\\';
            quoted += char(c);
        } else if (c < 0x20 || c >= 0x7f) {
            quoted += "\\x";
            quoted += kHex[c >> 4];
            quoted += kHex[c & 0xf];
        } else {
            quoted += char(c);
        }
    }
    quoted += '"';
    if (text.size() > maxBytes) quoted += "...";
    return quoted;
}

}  // namespace modeflow
