#pragma once
/// @file InputScript.h
/// Timed input replayed into `modeflow stir --script FILE`, so a session can be reproduced and
/// tested without a person at the mouse. One event per line, `#` starts a comment:
///
///     # time  event   arguments          (time in seconds of the window's clock)
///     0.5     down    0.30 0.50          left button pressed at window fractions x, y (y down)
///     0.6     move    0.40 0.50          pointer moved
///     0.8     up      0.50 0.50          left button released
///     0.2     rdown / rup  x y           the right button (orbit the camera: 3D, surfaces)
///     1.0     key     space              a key by name (StirKeys.h: space, ], [, escape, a letter)
///     1.2     scroll  1                  the wheel, notches
///     1.5     resize  800 600            the window's new size in screen units
///
/// Times never decrease. With `--frames N` the window's clock is the simulation's frame clock,
/// so a script gives the same result on every machine.

#include <filesystem>
#include <string>
#include <vector>

#include "engine/display/InputEvent.h"

namespace modeflow::stir {

struct TimedEvent {
    double time = 0.0;
    display::InputEvent event;
};

/// The events of a script's text; `source` names it in error messages, which quote the script's
/// words escaped and shortened (engine/core/PrintableText.h).
/// @throw modeflow::Error "SOURCE:LINE: why" for an unknown event or key, missing, extra or
///        non-numeric arguments, numbers that are not finite, fractions outside [0, 1], sizes
///        outside 1..kMaxWindowSide or decreasing times.
std::vector<TimedEvent> parseInputScript(const std::string& text, const std::string& source);
/// parseInputScript of a file. @throw modeflow::Error also when it cannot be read or is not a
///        regular file of at most 16 MiB (a folder, a FIFO or /dev/zero is refused at once).
std::vector<TimedEvent> readInputScript(const std::filesystem::path& path);

}  // namespace modeflow::stir
