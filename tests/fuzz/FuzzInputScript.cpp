/// Fuzz target: the `stir --script` parser, and what it promises of the events it accepts.

#include <cmath>
#include <string>

#include "engine/stir/InputScript.h"
#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {

bool inputScript(std::string_view bytes) {
    std::vector<stir::TimedEvent> events;
    if (!acceptedOrRefused(
            [&] { events = stir::parseInputScript(std::string(bytes), "fuzz.txt"); }))
        return false;
    double previous = 0.0;
    for (const stir::TimedEvent& timed : events) {
        require(std::isfinite(timed.time) && timed.time >= previous,
                "event times are not finite and ordered");
        previous = timed.time;
        const display::InputEvent& e = timed.event;
        switch (e.kind) {
            case display::InputKind::ButtonDown:
            case display::InputKind::ButtonUp:
            case display::InputKind::Move:
                require(e.x >= 0.0 && e.x <= 1.0 && e.y >= 0.0 && e.y <= 1.0,
                        "a pointer is outside the window");
                break;
            case display::InputKind::Scroll:
                require(std::isfinite(e.y), "a scroll is not finite");
                break;
            case display::InputKind::Resize:
                require(e.width >= 1 && e.width <= display::kMaxWindowSide && e.height >= 1 &&
                            e.height <= display::kMaxWindowSide,
                        "a window size is out of range");
                break;
            case display::InputKind::Key:
                require(e.key != 0, "a key event without a key");
                break;
        }
    }
    return true;
}

}  // namespace modeflow::fuzz
