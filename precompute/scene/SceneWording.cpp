/// @file SceneWording.cpp

#include "precompute/scene/SceneWording.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <vector>

#include "engine/core/SceneKeywords.h"

namespace modeflow::scene {
namespace {

/// Optimal-string-alignment distance, case-insensitive: a swapped pair of letters counts once,
/// which is the most common typo ("grdi").
std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
    auto lower = [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
                lower(a[i - 2]) == lower(b[j - 1])) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}

}  // namespace

bool contains(std::span<const std::string_view> list, std::string_view item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

std::optional<std::string_view> closest(std::string_view word,
                                        std::span<const std::string_view> candidates) {
    const std::size_t allowed = word.size() <= 3 ? 1 : word.size() <= 6 ? 2 : word.size() / 3;
    std::optional<std::string_view> best;
    std::size_t bestDistance = allowed + 1;
    for (std::string_view c : candidates) {
        // The distance is at least the difference in length: a megabyte-long word is no typo.
        const std::size_t gap =
            word.size() > c.size() ? word.size() - c.size() : c.size() - word.size();
        if (gap >= bestDistance) continue;
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

std::string joinWords(std::span<const std::string_view> words, std::string_view last) {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i) {
        // Appended piecewise: GCC 12 warns (-Wrestrict, falsely) on " " + std::string(last).
        if (i > 0 && i + 1 == words.size())
            out.append(" ").append(last).append(" ");
        else if (i > 0)
            out += ", ";
        out += words[i];
    }
    return out;
}

std::string formatNumber(double x) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return ec == std::errc{} ? std::string(buffer, end) : std::to_string(x);
}

std::string roughNumber(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2g", x);
    return buffer;
}

const char* axisName(int axis) {
    static constexpr const char* names[] = {"x", "y", "z"};
    return names[axis];
}

std::string sideName(int side) {
    return std::string(keywords::kSideNames[side]);
}

int sideNamed(std::string_view name, int dim) {
    for (int side = 0; side < 2 * dim; ++side)
        if (name == sideName(side)) return side;
    return -1;
}

std::string sideNames(int dim) {
    return dim == 3 ? "x_min, x_max, y_min, y_max, z_min or z_max" : "x_min, x_max, y_min or y_max";
}

}  // namespace modeflow::scene
