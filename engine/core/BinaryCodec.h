#pragma once
/// @file BinaryCodec.h
/// Little-endian binary records for modeflow's files (basis caches, checkpoints, smoke masks):
/// plain values, strings and arrays appended to a byte string, read back in the same order with
/// every length checked against the bytes that are left, so a damaged file is refused with a
/// message and never misread. Each file type adds its magic, version and checksum around them.

#include <cstdint>
#include <cstring>
#include <functional>
#include <istream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <bit>

#include "engine/core/Checksum.h"

static_assert(std::endian::native == std::endian::little, "modeflow's files are little-endian");

namespace modeflow {

/// 64-bit FNV-1a; stable across platforms and runs (it names cache files by their keys; file
/// contents are checked with Checksum.h's faster hash).
std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ull);

class ByteWriter {
public:
    template <typename T>
    void pod(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        mBytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    /// A count, then the values.
    template <typename T>
    void array(const T* values, std::size_t count) {
        pod<std::uint64_t>(count);
        this->values(values, count);
    }
    /// The values alone, for a record that states their number otherwise (a matrix's rows and
    /// columns); ByteReader::read reads them back.
    template <typename T>
    void values(const T* values, std::size_t count) {
        static_assert(std::is_trivially_copyable_v<T>);
        mBytes.append(reinterpret_cast<const char*>(values), count * sizeof(T));
    }
    template <typename T>
    void vector(const std::vector<T>& values) {
        array(values.data(), values.size());
    }
    void string(std::string_view text) { array(text.data(), text.size()); }

    const std::string& bytes() const { return mBytes; }

private:
    std::string mBytes;
};

class ByteReader {
public:
    using Describe = std::function<std::string(std::string_view why)>;

    /// `describe(why)` makes the message of the Error thrown when the bytes do not hold what is
    /// read ("truncated", ...), e.g. naming the file and what to do about it.
    ByteReader(std::string_view bytes, Describe describe)
        : mBytes(bytes), mSize(bytes.size()), mDescribe(std::move(describe)) {}
    /// The next `size` bytes of `in`, read as they are asked for: a file of gigabytes (a basis
    /// cache at N = 10 000) is decoded without a second copy of it in memory.
    ByteReader(std::istream& in, std::uint64_t size, Describe describe)
        : mStream(&in), mSize(size), mDescribe(std::move(describe)) {}

    template <typename T>
    T pod() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        read(&value, sizeof(T));
        return value;
    }
    /// A count written by ByteWriter::array, checked against the bytes left before anything is
    /// allocated.
    std::uint64_t count(std::size_t elementSize) {
        const auto n = pod<std::uint64_t>();
        if (elementSize != 0 && n > remaining() / elementSize)
            fail("truncated or corrupt (a length runs past the end)");
        return n;
    }
    template <typename T>
    std::vector<T> vector() {
        static_assert(std::is_trivially_copyable_v<T>);
        std::vector<T> values(count(sizeof(T)));
        read(values.data(), values.size() * sizeof(T));
        return values;
    }
    std::string string() {
        std::string text(count(1), '\0');
        read(text.data(), text.size());
        return text;
    }
    /// The next `n` bytes into `to` (which may be null when n is 0), e.g. values whose number a
    /// record states otherwise (ByteWriter::values).
    void read(void* to, std::size_t n);
    void skip(std::size_t n);

    std::uint64_t remaining() const { return mSize - mAt; }
    bool atEnd() const { return mAt == mSize; }
    /// The checksum (Checksum.h) of the bytes read so far, for the one that follows them.
    std::uint64_t hash() const { return mChecksum.value(); }
    [[noreturn]] void fail(std::string_view why) const;

private:
    std::string_view mBytes;
    std::istream* mStream = nullptr;
    std::uint64_t mSize = 0;
    std::uint64_t mAt = 0;
    Checksum mChecksum;
    Describe mDescribe;
};

}  // namespace modeflow
