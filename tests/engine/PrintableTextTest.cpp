/// @file PrintableTextTest.cpp
/// Text from input files quoted in messages: control bytes escaped, UTF-8 kept, long text cut.

#include <gtest/gtest.h>

#include <string>

#include "engine/core/PrintableText.h"

namespace modeflow {
namespace {

TEST(PrintableText, EscapesControlCharactersAndBrokenUtf8) {
    EXPECT_EQ(printableText("abc 1.5"), "abc 1.5");
    EXPECT_EQ(printableText("\x1b[2Jx\x7f"), "\\x1b[2Jx\\x7f");
    EXPECT_EQ(printableText(std::string("a\0b", 3)), "a\\x00b");
    EXPECT_EQ(printableText("caf\xc3\xa9 \xe2\x86\x92"), "caf\xc3\xa9 \xe2\x86\x92");  // é →
    EXPECT_EQ(printableText("\xc2\x9b"
                            "31m"),
              "\\xc2\\x9b31m");                          // C1 CSI: a terminal command
    EXPECT_EQ(printableText("\xff\xc3"), "\\xff\\xc3");  // not UTF-8, cut sequence
}

TEST(PrintableText, EscapesWhatLooksLikeUtf8ButIsNot) {
    EXPECT_EQ(printableText("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");           // an overlong '/'
    EXPECT_EQ(printableText("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a UTF-16 surrogate
    EXPECT_EQ(printableText("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // beyond U+10FFFF
    EXPECT_EQ(printableText("\xf0\x9f\x8c\x80 \xe2\x82\xac"),
              "\xf0\x9f\x8c\x80 \xe2\x82\xac");  // 🌀 €
}

TEST(PrintableText, CutsLongTextAfterMaxCharacters) {
    EXPECT_EQ(printableText(std::string(1000000, '7'), 5), "77777...");
    EXPECT_EQ(printableText("12345", 5), "12345");
    EXPECT_EQ(printableText("\x01\x02\x03", 2), "\\x01\\x02...");
}

}  // namespace
}  // namespace modeflow
