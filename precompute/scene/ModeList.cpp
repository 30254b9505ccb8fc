/// @file ModeList.cpp

#include "precompute/scene/ModeList.h"

#include <cctype>
#include <charconv>

#include "engine/core/PrintableText.h"
#include "precompute/scene/SceneLoader.h"

namespace modeflow {
namespace scene {

std::optional<std::string> parseModeList(std::string_view text, std::vector<ModeRange>& out) {
    auto isSpace = [](char c) { return c == ' ' || c == '\t'; };
    std::size_t pos = 0;
    auto skipSpace = [&] {
        while (pos < text.size() && isSpace(text[pos])) ++pos;
    };
    auto readNumber = [&](int& value) -> std::optional<std::string> {
        skipSpace();
        const char* begin = text.data() + pos;
        const char* end = text.data() + text.size();
        if (begin == end || !std::isdigit(static_cast<unsigned char>(*begin))) {
            return "expected a mode number at position " + std::to_string(pos + 1);
        }
        const auto [stop, ec] = std::from_chars(begin, end, value);
        if (ec == std::errc::result_out_of_range) {
            return "mode number at position " + std::to_string(pos + 1) + " is too large";
        }
        pos += static_cast<std::size_t>(stop - begin);
        skipSpace();
        return std::nullopt;
    };

    out.clear();
    skipSpace();
    if (pos == text.size()) return std::string("empty mode list");
    while (true) {
        ModeRange range;
        if (auto problem = readNumber(range.first)) return problem;
        range.last = range.first;
        if (pos < text.size() && text[pos] == '-') {
            ++pos;
            if (auto problem = readNumber(range.last)) return problem;
        }
        // Appended piecewise: GCC 12 warns (-Wrestrict, falsely) on "-" + std::to_string(...).
        std::string item = std::to_string(range.first);
        if (range.last != range.first) item.append("-").append(std::to_string(range.last));
        if (range.first < 1) return "modes are numbered from 1, got " + item;
        if (range.last < range.first) return "range " + item + " ends before it starts";
        if (!out.empty() && range.first <= out.back().last) {
            return "range " + item + " overlaps or comes before the previous one (" +
                   std::to_string(out.back().first) + "-" + std::to_string(out.back().last) +
                   "); ranges must be sorted and disjoint";
        }
        out.push_back(range);
        if (pos == text.size()) return std::nullopt;
        if (text[pos] != ',') {
            return "unexpected character '" + printableText(text.substr(pos, 1)) +
                   "' at position " + std::to_string(pos + 1) + " (expected ',' or '-')";
        }
        ++pos;
    }
}

}  // namespace scene

std::vector<ModeRange> parseModeRanges(std::string_view text, std::string_view key) {
    std::vector<ModeRange> ranges;
    if (auto problem = scene::parseModeList(text, ranges)) {
        throw Error(std::string(key) + ": bad mode list \"" + printableText(text) +
                    "\": " + *problem);
    }
    return ranges;
}

}  // namespace modeflow
