#include "tools/modeflow/NumberOptions.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "engine/core/PrintableText.h"

namespace modeflow::cli {
namespace {

/// `text` as a finite number, or nothing when it is not one whole (nan, inf, "2x").
std::optional<double> finiteNumber(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

CLI::Validator finiteAtLeast(double minimum, bool inclusive, const std::string& what) {
    return CLI::Validator(
        [minimum, inclusive, what](std::string& text) -> std::string {
            const std::optional<double> value = finiteNumber(text);
            if (value && (*value > minimum || (inclusive && *value == minimum))) return "";
            return "must be " + what + ", got \"" + printableText(text) + "\"";
        },
        inclusive ? "NUMBER >= 0" : "NUMBER > 0");
}

}  // namespace

CLI::Validator finitePositive() {
    return finiteAtLeast(0.0, false, "a finite number greater than 0");
}

CLI::Validator finiteNonNegative() {
    return finiteAtLeast(0.0, true, "a finite number of at least 0");
}

CLI::Validator countUpTo(long long maximum) {
    return CLI::Validator(
        [maximum](std::string& text) -> std::string {
            long long value = 0;
            const auto [end, error] =
                std::from_chars(text.data(), text.data() + text.size(), value);
            if (error == std::errc() && end == text.data() + text.size() && value >= 1 &&
                value <= maximum)
                return "";
            return "must be a whole number from 1 to " + std::to_string(maximum) + ", got \"" +
                   printableText(text) + "\"";
        },
        "1.." + std::to_string(maximum));
}

}  // namespace modeflow::cli
