#include "engine/stir/StirKeys.h"

#include <GLFW/glfw3.h>

#include <array>
#include <cctype>

namespace modeflow::stir {
namespace {

constexpr std::array kBindings{
    KeyBinding{GLFW_KEY_SPACE, "space", StirAction::Pause, "pause / run"},
    KeyBinding{GLFW_KEY_S, "s", StirAction::Step, "one frame (paused)"},
    KeyBinding{GLFW_KEY_R, "r", StirAction::Reset, "reset"},
    KeyBinding{GLFW_KEY_I, "i", StirAction::Integrator, "integrator: explicit / midpoint"},
    KeyBinding{GLFW_KEY_RIGHT_BRACKET, "]", StirAction::ViscosityUp, "viscosity x2"},
    KeyBinding{GLFW_KEY_LEFT_BRACKET, "[", StirAction::ViscosityDown, "viscosity /2"},
    KeyBinding{GLFW_KEY_B, "b", StirAction::NextBasis, "next shaped basis"},
    KeyBinding{GLFW_KEY_M, "m", StirAction::Paddle, "mouse: stir force / paddle"},
    KeyBinding{GLFW_KEY_V, "v", StirAction::Arrows, "velocity arrows (2D)"},
    KeyBinding{GLFW_KEY_P, "p", StirAction::Screenshot, "screenshot (PNG)"},
    KeyBinding{GLFW_KEY_H, "h", StirAction::Help, "this help"},
    KeyBinding{GLFW_KEY_Q, "q", StirAction::Quit, "quit"},
    KeyBinding{GLFW_KEY_ESCAPE, "escape", StirAction::Quit, "quit"},
};

}  // namespace

std::span<const KeyBinding> keyBindings() {
    return kBindings;
}

std::optional<StirAction> actionOfKey(int key) {
    for (const KeyBinding& b : kBindings)
        if (b.key == key) return b.action;
    return std::nullopt;
}

std::optional<int> keyFromName(std::string_view name) {
    for (const KeyBinding& b : kBindings)
        if (name == b.name) return b.key;
    // GLFW codes of letters and digits are their upper-case ASCII codes.
    if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
        return std::toupper(static_cast<unsigned char>(name[0]));
    return std::nullopt;
}

HelpColumns helpColumns() {
    HelpColumns help{"keys\n", "\n"};
    for (const KeyBinding& b : kBindings) {
        help.keys += std::string(b.name) + "\n";
        help.actions += std::string(b.help) + "\n";
    }
    help.keys += "\nmouse\nleft drag\nright drag\nwheel";
    help.actions +=
        "\n\nstir (or move the paddle)\norbit the camera (3D, surfaces)\nzoom (3D, surfaces)";
    return help;
}

}  // namespace modeflow::stir
