/// User text in error messages: control characters and broken UTF-8 escaped, the rest kept.

#include <gtest/gtest.h>

#include <string>

#include "engine/format/QuotedText.h"

namespace modeflow {
namespace {

TEST(QuotedTextTest, PrintableTextEscapesControlsAndBrokenUtf8Only) {
    EXPECT_EQ(printableText("plain ASCII, κ² and é kept"), "plain ASCII, κ² and é kept");
    EXPECT_EQ(printableText(std::string("a\x01\x1b[2J\x7f\n\0z", 10)),
              "a\\x01\\x1b[2J\\x7f\\x0a\\x00z");
    EXPECT_EQ(printableText("cut \xc3"), "cut \\xc3") << "a lead byte without its continuation";
    EXPECT_EQ(printableText("\xc0\x80"), "\\xc0\\x80") << "an overlong NUL";
    EXPECT_EQ(printableText("\xed\xa0\x80"), "\\xed\\xa0\\x80") << "a UTF-16 surrogate";
    EXPECT_EQ(printableText("\xc2\x85"), "\\xc2\\x85") << "a C1 control (NEL)";
    EXPECT_EQ(printableText("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80") << "beyond U+10FFFF";
    EXPECT_EQ(printableText("back\\slash \"quotes\""), "back\\slash \"quotes\"");
}

TEST(QuotedTextTest, QuotedTextQuotesEscapesAndCuts) {
    EXPECT_EQ(quotedText("space"), "\"space\"");
    EXPECT_EQ(quotedText("say \"hi\" \\ \x07"), "\"say \\\"hi\\\" \\\\ \\x07\"");
    EXPECT_EQ(quotedText(std::string(100, 'k'), 5), "\"kkkkk\"...");
    EXPECT_EQ(quotedText("é", 1), "\"\\xc3\"...")
        << "a cut through a character escapes its first byte";
}

}  // namespace
}  // namespace modeflow
