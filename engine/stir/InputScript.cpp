#include "engine/stir/InputScript.h"

#include <fstream>
#include <sstream>

#include "engine/core/Error.h"
#include "engine/stir/StirKeys.h"

namespace modeflow::stir {
namespace {

using display::InputKind;
using display::MouseButton;

/// The next word of `line` as a number, or an error naming `what`.
double number(std::istringstream& line, const std::string& where, const char* what) {
    std::string word;
    if (!(line >> word)) throw Error(where + ": missing " + what);
    try {
        std::size_t used = 0;
        const double value = std::stod(word, &used);
        if (used == word.size()) return value;
    } catch (const std::exception&) {
    }
    throw Error(where + ": " + what + " \"" + word + "\" is not a number");
}

double fraction(std::istringstream& line, const std::string& where, const char* what) {
    const double value = number(line, where, what);
    if (!(value >= 0.0 && value <= 1.0))
        throw Error(where + ": " + what + " " + std::to_string(value) +
                    " is not a fraction of the window in [0, 1]");
    return value;
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
        timed.time = number(line, where, "time");
        if (timed.time < 0.0) throw Error(where + ": time " + std::to_string(timed.time) + " is negative");
        if (!events.empty() && timed.time < events.back().time)
            throw Error(where + ": time " + std::to_string(timed.time) + " is before the previous event's");
        std::string name;
        if (!(line >> name)) throw Error(where + ": missing the event after the time");
        if (name == "down" || name == "up" || name == "rdown" || name == "rup" || name == "move") {
            const InputKind kind = name == "move"                   ? InputKind::Move
                                   : name == "down" || name == "rdown" ? InputKind::ButtonDown
                                                                       : InputKind::ButtonUp;
            const MouseButton button = name[0] == 'r' ? MouseButton::Right : MouseButton::Left;
            timed.event = pointerEvent(kind, button, line, where);
        } else if (name == "key") {
            std::string key;
            if (!(line >> key)) throw Error(where + ": missing the key's name");
            const auto code = keyFromName(key);
            if (!code) throw Error(where + ": unknown key \"" + key + "\"");
            timed.event = {InputKind::Key};
            timed.event.key = *code;
        } else if (name == "scroll") {
            timed.event = {InputKind::Scroll};
            timed.event.y = number(line, where, "notches");
        } else if (name == "resize") {
            timed.event = {InputKind::Resize};
            const double w = number(line, where, "width"), h = number(line, where, "height");
            if (w < 1.0 || h < 1.0 || w != int(w) || h != int(h))
                throw Error(where + ": window size must be whole numbers of at least 1");
            timed.event.width = int(w);
            timed.event.height = int(h);
        } else {
            throw Error(where + ": unknown event \"" + name +
                        "\" (down, up, move, rdown, rup, key, scroll, resize)");
        }
        std::string extra;
        if (line >> extra) throw Error(where + ": unexpected \"" + extra + "\" after the event");
        events.push_back(timed);
    }
    return events;
}

std::vector<TimedEvent> readInputScript(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot read the input script " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return parseInputScript(text.str(), path.string());
}

}  // namespace modeflow::stir
