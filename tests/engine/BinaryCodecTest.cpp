/// BinaryCodec: what is written reads back the same, and damaged bytes are refused with the
/// caller's message before anything is allocated for them.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"

namespace modeflow {
namespace {

ByteReader readerOf(const std::string& bytes) {
    return ByteReader(bytes,
                      [](std::string_view why) { return "test record is " + std::string(why); });
}

TEST(BinaryCodec, ValuesStringsAndArraysRoundTrip) {
    ByteWriter w;
    w.pod(std::int32_t(-7));
    w.pod(2.5);
    w.string("key text");
    w.vector(std::vector<std::int64_t>{1, -2, 3});
    w.vector(std::vector<double>{});
    const double block[] = {0.5, -1.0};
    w.values(block, 2);
    const std::string bytes = w.bytes();
    ByteReader r = readerOf(bytes);
    EXPECT_EQ(r.pod<std::int32_t>(), -7);
    EXPECT_EQ(r.pod<double>(), 2.5);
    EXPECT_EQ(r.string(), "key text");
    EXPECT_EQ(r.vector<std::int64_t>(), (std::vector<std::int64_t>{1, -2, 3}));
    EXPECT_TRUE(r.vector<double>().empty());
    EXPECT_EQ(r.bytes(2 * sizeof(double)),
              std::string_view(reinterpret_cast<const char*>(block), sizeof block));
    EXPECT_TRUE(r.atEnd());
}

TEST(BinaryCodec, TruncatedBytesAreRefusedWithTheCallersMessage) {
    ByteWriter w;
    w.vector(std::vector<double>{1.0, 2.0, 3.0});
    const std::string bytes = w.bytes().substr(0, w.bytes().size() - 1);
    ByteReader r = readerOf(bytes);
    try {
        r.vector<double>();
        FAIL() << "a truncated array was read";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("test record is truncated", 0), 0u) << e.what();
    }
}

TEST(BinaryCodec, AHugeCountIsRefusedBeforeAnyAllocation) {
    ByteWriter w;
    w.pod(std::uint64_t(1) << 62);  // a count no file of this size can hold
    const std::string bytes = w.bytes();
    ByteReader r = readerOf(bytes);
    EXPECT_THROW(r.vector<double>(), Error);
    ByteReader again = readerOf(bytes);
    EXPECT_THROW(again.string(), Error);
}

TEST(BinaryCodec, Fnv1aMatchesItsPublishedValues) {
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
}

}  // namespace
}  // namespace modeflow
