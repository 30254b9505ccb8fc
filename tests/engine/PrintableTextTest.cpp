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
    EXPECT_EQ(printableText("\xc2\x9b" "31m"), "\\xc2\\x9b31m");  // C1 CSI: a terminal command
    EXPECT_EQ(printableText("\xff\xc3"), "\\xff\\xc3");           // not UTF-8, cut sequence
}

TEST(PrintableText, CutsLongTextAfterMaxCharacters) {
    EXPECT_EQ(printableText(std::string(1000000, '7'), 5), "77777...");
    EXPECT_EQ(printableText("12345", 5), "12345");
    EXPECT_EQ(printableText("\x01\x02\x03", 2), "\\x01\\x02...");
}

}  // namespace
}  // namespace modeflow
