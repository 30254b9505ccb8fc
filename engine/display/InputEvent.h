#pragma once
/// @file InputEvent.h
/// What the user does to a window, in a form independent of the window system: the window
/// reports these (Window::poll) and a script replays them (engine/stir/InputScript), so both
/// drive the application through the same code. Pointer positions are fractions of the window,
/// x to the right and y downwards in [0, 1], so a script means the same at any window size.

namespace modeflow::display {

enum class InputKind {
    ButtonDown,  ///< a mouse button pressed at (x, y)
    ButtonUp,    ///< released at (x, y)
    Move,        ///< the pointer moved to (x, y)
    Key,         ///< a key pressed (or repeating): `key`
    Scroll,      ///< the wheel turned by `y` notches (positive: away from the user)
    Resize,      ///< (scripts) the window is to become width × height screen units
};

enum class MouseButton { Left, Right };

/// The widest or tallest window a script or the command line may ask for, in screen units.
inline constexpr int kMaxWindowSide = 16384;

struct InputEvent {
    InputKind kind = InputKind::Move;
    double x = 0.0;
    double y = 0.0;
    MouseButton button = MouseButton::Left;
    int key = 0;  ///< a GLFW_KEY_* code
    int width = 0;
    int height = 0;
};

}  // namespace modeflow::display
