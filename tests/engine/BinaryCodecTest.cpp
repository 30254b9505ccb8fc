/// BinaryCodec: what is written reads back the same, from memory or streamed from a file, and
/// damaged bytes are refused with the caller's message before anything is allocated for them.

#include <algorithm>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"

namespace modeflow {
namespace {

std::string describe(std::string_view why) {
    return "test record is " + std::string(why);
}

ByteReader readerOf(const std::string& bytes) {
    return ByteReader(bytes, describe);
}

/// A reader of `bytes` that reads them from a stream, as the cache reader does.
struct StreamedReader {
    explicit StreamedReader(const std::string& bytes, std::uint64_t declared)
        : in(bytes), reader(in, declared, describe) {}
    explicit StreamedReader(const std::string& bytes) : StreamedReader(bytes, bytes.size()) {}
    std::istringstream in;
    ByteReader reader;
};

/// Reads back what ValuesStringsAndArraysRoundTrip writes.
void expectRoundTrip(ByteReader& r, const double (&block)[2]) {
    EXPECT_EQ(r.pod<std::int32_t>(), -7);
    EXPECT_EQ(r.pod<double>(), 2.5);
    EXPECT_EQ(r.string(), "key text");
    EXPECT_EQ(r.vector<std::int64_t>(), (std::vector<std::int64_t>{1, -2, 3}));
    EXPECT_TRUE(r.vector<double>().empty());
    double values[2];
    r.read(values, sizeof values);
    EXPECT_EQ(values[0], block[0]);
    EXPECT_EQ(values[1], block[1]);
    EXPECT_TRUE(r.atEnd());
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
    expectRoundTrip(r, block);
    StreamedReader streamed(bytes);
    expectRoundTrip(streamed.reader, block);
}

TEST(BinaryCodec, TheHashCoversTheBytesReadSoFar) {
    ByteWriter w;
    w.string("checked part");
    w.pod(std::uint64_t(99));
    const std::string bytes = w.bytes();
    const std::uint64_t expected = checksum64(std::string_view(bytes).substr(0, bytes.size() - 8));
    ByteReader r = readerOf(bytes);
    StreamedReader streamed(bytes);
    for (ByteReader* reader : {&r, &streamed.reader}) {
        reader->string();
        EXPECT_EQ(reader->hash(), expected);
    }
}

TEST(BinaryCodec, AStreamEndingBeforeItsDeclaredSizeIsRefused) {
    ByteWriter w;
    w.vector(std::vector<double>{1.0, 2.0, 3.0});
    StreamedReader streamed(w.bytes(), w.bytes().size() + 64);
    try {
        streamed.reader.vector<double>();
        streamed.reader.pod<double>();
        FAIL() << "a stream shorter than declared was read";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("test record is unreadable to its end", 0), 0u)
            << e.what();
    }
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
    StreamedReader streamed(bytes);
    EXPECT_THROW(streamed.reader.vector<double>(), Error);
}

TEST(BinaryCodec, ChecksumIsXxh3AndStreamsAsOneCall) {
    EXPECT_EQ(checksum64(""), 0x2d06800538d394c2ull);  // XXH3-64's published empty-input value
    std::string bytes(3'000'017, '\0');
    std::uint64_t state = 88172645463325252ull;
    for (char& c : bytes) {  // xorshift: every byte matters to the comparison
        state ^= state << 13, state ^= state >> 7, state ^= state << 17;
        c = char(state);
    }
    // Pieces of odd sizes, across the hash's internal 256-byte stripes and 1 KiB blocks.
    Checksum streamed;
    std::size_t at = 0;
    for (std::size_t piece = 1; at < bytes.size(); piece = piece * 3 + 1) {
        const std::size_t n = std::min(piece, bytes.size() - at);
        streamed.update(std::string_view(bytes).substr(at, n));
        at += n;
    }
    EXPECT_EQ(streamed.value(), checksum64(bytes));
    bytes[1'234'567] ^= 1;
    EXPECT_NE(streamed.value(), checksum64(bytes)) << "one flipped bit changes the checksum";
}

TEST(BinaryCodec, Fnv1aMatchesItsPublishedValues) {
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
}

}  // namespace
}  // namespace modeflow
