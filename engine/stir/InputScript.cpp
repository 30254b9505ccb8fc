#include "engine/stir/InputScript.h"

#include <cmath>
#include <sstream>

#include "engine/core/Error.h"
#include "engine/core/InputFile.h"
#include "engine/core/PrintableText.h"
#include "engine/stir/StirKeys.h"

namespace modeflow::stir {
namespace {

using display::InputKind;
using display::MouseButton;

/// The largest script read (16 MiB, over half a million events): a wrong file (a device such as
/// /dev/zero, a video) fails at once instead of filling memory.
constexpr std::uintmax_t kMaxScriptBytes = std::uintmax_t{1} << 24;

/// A number of the script and its word as written, which messages repeat.
struct Number {
    double value = 0.0;
    std::string word;
};

/// The next word of `line` as a finite number, or an error naming `what`.
Number number(std::istringstream& line, const std::string& where, const char* what) {
    std::string word;
    if (!(line >> word)) throw Error(where + ": missing " + what);
    try {
        std::size_t used = 0;
        const double value = std::stod(word, &used);
        if (used == word.size() && std::isfinite(value)) return {value, word};
    } catch (const std::exception&) {
    }
    throw Error(where + ": " + what + " \"" + printableText(word) + "\" is not a finite number");
}

double fraction(std::istringstream& line, const std::string& where, const char* what) {
    const Number n = number(line, where, what);
    if (!(n.value >= 0.0 && n.value <= 1.0))
        throw Error(where + ": " + what + " \"" + printableText(n.word) +
                    "\" is not a fraction of the window in [0, 1]");
    return n.value;
}

display::InputEvent pointerEvent(InputKind kind, MouseButton button, std::istringstream& line,
                                 const std::string& where) {
    display::InputEvent e{kind};
    e.button = button;
    e.x = fraction(line, where, "x");
    e.y = fraction(line, where, "y");
    return e;
}

}  // namespace

std::vector<TimedEvent> parseInputScript(const std::string& text, const std::string& source) {
    std::vector<TimedEvent> events;
    std::istringstream lines(text);
    std::string raw;
    for (int lineNumber = 1; std::getline(lines, raw); ++lineNumber) {
        const std::string where = source + ":" + std::to_string(lineNumber);
        std::istringstream line(raw.substr(0, raw.find('#')));
        std::string first;
        if (!(line >> first)) continue;
        line.seekg(0);
        TimedEvent timed;
        const Number time = number(line, where, "time");
        timed.time = time.value;
        if (timed.time < 0.0)
            throw Error(where + ": time \"" + printableText(time.word) + "\" is negative");
        if (!events.empty() && timed.time < events.back().time)
            throw Error(where + ": time \"" + printableText(time.word) +
                        "\" is before the previous event's");
        std::string name;
        if (!(line >> name)) throw Error(where + ": missing the event after the time");
        if (name == "down" || name == "up" || name == "rdown" || name == "rup" || name == "move") {
            const InputKind kind = name == "move"                      ? InputKind::Move
                                   : name == "down" || name == "rdown" ? InputKind::ButtonDown
                                                                       : InputKind::ButtonUp;
            const MouseButton button = name[0] == 'r' ? MouseButton::Right : MouseButton::Left;
            timed.event = pointerEvent(kind, button, line, where);
        } else if (name == "key") {
            std::string key;
            if (!(line >> key)) throw Error(where + ": missing the key's name");
            const auto code = keyFromName(key);
            if (!code) throw Error(where + ": unknown key \"" + printableText(key) + "\"");
            timed.event = {InputKind::Key};
            timed.event.key = *code;
        } else if (name == "scroll") {
            timed.event = {InputKind::Scroll};
            timed.event.y = number(line, where, "notches").value;
        } else if (name == "resize") {
            timed.event = {InputKind::Resize};
            const double w = number(line, where, "width").value,
                         h = number(line, where, "height").value;
            const auto side = [](double x) {
                return x >= 1.0 && x <= display::kMaxWindowSide && x == std::floor(x);
            };
            if (!side(w) || !side(h))
                throw Error(where + ": window size must be whole numbers from 1 to " +
                            std::to_string(display::kMaxWindowSide));
            timed.event.width = int(w);
            timed.event.height = int(h);
        } else {
            throw Error(where + ": unknown event \"" + printableText(name) +
                        "\" (down, up, move, rdown, rup, key, scroll, resize)");
        }
        std::string extra;
        if (line >> extra)
            throw Error(where + ": unexpected \"" + printableText(extra) + "\" after the event");
        events.push_back(timed);
    }
    return events;
}

std::vector<TimedEvent> readInputScript(const std::filesystem::path& path) {
    return parseInputScript(readInputFile(path, "input script", kMaxScriptBytes), path.string());
}

}  // namespace modeflow::stir
