#pragma once
/// @file StirKeys.h
/// The keys of `modeflow stir`: one table gives each key its action, its name in scripts and
/// its line in the help overlay, so the three never disagree.

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace modeflow::stir {

enum class StirAction {
    Pause,          ///< stop or restart the clock
    Step,           ///< while paused: advance one frame
    Reset,          ///< back to the initial velocity and no smoke
    Integrator,     ///< explicit Euler ↔ implicit midpoint
    ViscosityUp,    ///< ν × 2 (from 0: the first step)
    ViscosityDown,  ///< ν / 2 (below the first step: 0)
    NextBasis,      ///< the next shaped basis the cache holds
    Paddle,         ///< mouse drags stir with a force ↔ move a solid paddle
    Arrows,         ///< 2D: show or hide velocity arrows
    Screenshot,     ///< the window as PNG
    Help,           ///< show or hide the key list
    Quit,
};

struct KeyBinding {
    int key;           ///< GLFW_KEY_* code
    const char* name;  ///< as scripts write it
    StirAction action;
    const char* help;
};

/// Every key binding, in help order.
std::span<const KeyBinding> keyBindings();
/// The action of a key, if it has one.
std::optional<StirAction> actionOfKey(int key);
/// A key's GLFW code from its script name (a binding's name, or one letter or digit).
std::optional<int> keyFromName(std::string_view name);
/// The help overlay in two columns, line for line: the keys (and mouse buttons) and what they do.
struct HelpColumns {
    std::string keys;
    std::string actions;
};
HelpColumns helpColumns();

}  // namespace modeflow::stir
