/// Input scripts of `modeflow stir --script` and the key names they use.

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <algorithm>

#include "engine/core/Error.h"
#include "engine/stir/InputScript.h"
#include "engine/stir/StirKeys.h"

namespace modeflow::stir {
namespace {

using display::InputKind;
using display::MouseButton;

TEST(InputScriptTest, ReadsEveryEventKind) {
    const auto events = parseInputScript(
        "# a drag, keys, the wheel and a resize\n"
        "0.5 down 0.3 0.5   # press\n"
        "\n"
        "0.6 move 0.4 0.5\n"
        "0.8 up 0.5 0.5\n"
        "0.8 rdown 0.1 0.2\n"
        "0.9 rup 0.2 0.2\n"
        "1.0 key space\n"
        "1.1 key ]\n"
        "1.1 key B\n"
        "1.2 scroll -2\n"
        "1.5 resize 800 600\n",
        "s");
    ASSERT_EQ(events.size(), 10u);
    EXPECT_EQ(events[0].event.kind, InputKind::ButtonDown);
    EXPECT_EQ(events[0].event.button, MouseButton::Left);
    EXPECT_DOUBLE_EQ(events[0].time, 0.5);
    EXPECT_DOUBLE_EQ(events[0].event.x, 0.3);
    EXPECT_EQ(events[1].event.kind, InputKind::Move);
    EXPECT_EQ(events[2].event.kind, InputKind::ButtonUp);
    EXPECT_EQ(events[3].event.button, MouseButton::Right);
    EXPECT_EQ(events[4].event.kind, InputKind::ButtonUp);
    EXPECT_EQ(events[5].event.key, GLFW_KEY_SPACE);
    EXPECT_EQ(events[6].event.key, GLFW_KEY_RIGHT_BRACKET);
    EXPECT_EQ(events[7].event.key, GLFW_KEY_B);
    EXPECT_EQ(events[8].event.kind, InputKind::Scroll);
    EXPECT_DOUBLE_EQ(events[8].event.y, -2.0);
    EXPECT_EQ(events[9].event.width, 800);
    EXPECT_EQ(events[9].event.height, 600);
}

TEST(InputScriptTest, RefusesBadLinesNamingThem) {
    const auto message = [](const std::string& text) {
        try {
            parseInputScript(text, "drag.txt");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("0.1 wiggle 0.2 0.2\n"), "drag.txt:1: unknown event \"wiggle\" (down, up, move, rdown, rup, key, scroll, resize)");
    EXPECT_EQ(message("0.1 move 0.2\n"), "drag.txt:1: missing y");
    EXPECT_EQ(message("\n0.1 move 1.5 0.2\n"), "drag.txt:2: x 1.500000 is not a fraction of the window in [0, 1]");
    EXPECT_EQ(message("0.5 key space\n0.4 key space\n"), "drag.txt:2: time 0.400000 is before the previous event's");
    EXPECT_EQ(message("0.1 key f13\n"), "drag.txt:1: unknown key \"f13\"");
    EXPECT_EQ(message("soon key r\n"), "drag.txt:1: time \"soon\" is not a number");
    EXPECT_EQ(message("0.1 up 0.2 0.2 0.3\n"), "drag.txt:1: unexpected \"0.3\" after the event");
    EXPECT_EQ(message("0.1 resize 0 100\n"), "drag.txt:1: window size must be whole numbers of at least 1");
    EXPECT_EQ(message("-1 key r\n"), "drag.txt:1: time -1.000000 is negative");
}

TEST(InputScriptTest, EveryKeyHasAScriptNameAndAHelpLine) {
    const HelpColumns help = helpColumns();
    EXPECT_EQ(std::count(help.keys.begin(), help.keys.end(), '\n'),
              std::count(help.actions.begin(), help.actions.end(), '\n'))
        << "the columns pair line for line";
    for (const KeyBinding& binding : keyBindings()) {
        EXPECT_EQ(keyFromName(binding.name), binding.key) << binding.name;
        EXPECT_EQ(actionOfKey(binding.key), binding.action) << binding.name;
        EXPECT_NE(help.actions.find(binding.help), std::string::npos) << binding.name;
        EXPECT_NE(help.keys.find(binding.name), std::string::npos) << binding.name;
    }
    EXPECT_FALSE(actionOfKey(GLFW_KEY_Z).has_value());
}

}  // namespace
}  // namespace modeflow::stir
