/// Input scripts of `modeflow stir --script` and the key names they use.

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "engine/core/Error.h"
#include "engine/stir/InputScript.h"
#include "engine/stir/StirKeys.h"
#include "tests/support/TestFolder.h"

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
    EXPECT_EQ(
        message("0.1 wiggle 0.2 0.2\n"),
        "drag.txt:1: unknown event \"wiggle\" (down, up, move, rdown, rup, key, scroll, resize)");
    EXPECT_EQ(message("0.1 move 0.2\n"), "drag.txt:1: missing y");
    EXPECT_EQ(message("\n0.1 move 1.5 0.2\n"),
              "drag.txt:2: x \"1.5\" is not a fraction of the window in [0, 1]");
    EXPECT_EQ(message("0.5 key space\n0.4 key space\n"),
              "drag.txt:2: time \"0.4\" is before the previous event's");
    EXPECT_EQ(message("0.1 key f13\n"), "drag.txt:1: unknown key \"f13\"");
    EXPECT_EQ(message("soon key r\n"), "drag.txt:1: time \"soon\" is not a finite number");
    EXPECT_EQ(message("0.1 up 0.2 0.2 0.3\n"), "drag.txt:1: unexpected \"0.3\" after the event");
    EXPECT_EQ(message("0.1 resize 0 100\n"),
              "drag.txt:1: window size must be whole numbers from 1 to 16384");
    EXPECT_EQ(message("-1 key r\n"), "drag.txt:1: time \"-1\" is negative");
}

TEST(InputScriptTest, RefusesNumbersThatAreNotFinite) {
    for (const std::string line : {"0 scroll nan", "nan key r", "inf key r", "0.1 move 0.5 -inf",
                                   "0.1 scroll 1e999", "0.1 resize infinity 100"}) {
        try {
            const auto events = parseInputScript(line + "\n", "s");
            ADD_FAILURE() << "accepted \"" << line << "\" as " << events.size() << " events";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("is not a finite number"), std::string::npos)
                << e.what();
        }
    }
    // Finite but far too large: refused by the range, and printed as written, not in 300 digits.
    try {
        parseInputScript("0 resize 1e300 100\n", "s");
        ADD_FAILURE() << "a window 1e300 units wide was accepted";
    } catch (const Error& e) {
        EXPECT_LT(std::string(e.what()).size(), 80u) << e.what();
    }
}

TEST(InputScriptTest, QuotesBinaryAndLongTextSafely) {
    const auto message = [](const std::string& text) {
        try {
            parseInputScript(text, "s");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string escape = message(std::string("0.1 \x1b[2J\x07\xff\x00 0.2\n", 16));
    EXPECT_EQ(escape,
              "s:1: unknown event \"\\x1b[2J\\x07\\xff\\x00\" (down, up, move, rdown, rup, key, "
              "scroll, resize)");
    const std::string longKey = message("0.1 key " + std::string(100000, 'k') + "\n");
    EXPECT_LT(longKey.size(), 100u) << longKey.substr(0, 200);
    EXPECT_NE(longKey.find("kkk...\""), std::string::npos) << longKey.substr(0, 200);
}

TEST(InputScriptTest, ReadingRefusesFoldersDevicesFifosAndHugeFiles) {
    const testing::TestFolder folder;
    const auto message = [](const std::filesystem::path& path) {
        try {
            readInputScript(path);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message(folder.path()),
              folder.path().string() + ": is a directory, not an input script");
    EXPECT_EQ(message("/dev/zero"), "/dev/zero: is a character device, not an input script");
    const auto fifo = folder / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(message(fifo), fifo.string() + ": is a FIFO, not an input script")
        << "a FIFO blocks its reader";
    const auto huge = folder / "huge.txt";
    std::ofstream(huge) << "0.1 key space\n";
    std::filesystem::resize_file(huge, std::uintmax_t{1} << 30);  // sparse: no disk used
    EXPECT_EQ(message(huge),
              huge.string() +
                  ": 1073741824 bytes is too large for an input script (at most 16 MiB); is "
                  "it the right file?");
    EXPECT_EQ(message(folder / "missing.txt"),
              (folder / "missing.txt").string() + ": no such input script");
    const auto good = folder / "good.txt";
    std::ofstream(good) << "0.1 key space\n0.2 scroll 1\n";
    EXPECT_EQ(readInputScript(good).size(), 2u);
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
