#pragma once
/// @file BinaryCodec.h
/// Little-endian binary records for modeflow's files (basis caches, checkpoints, smoke masks):
/// plain values, strings and arrays appended to a byte string, read back in the same order with
/// every length checked against the bytes that are left, so a damaged file is refused with a
/// message and never misread. Each file type adds its magic, version and checksum around them.

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <bit>

static_assert(std::endian::native == std::endian::little, "modeflow's files are little-endian");

namespace modeflow {

/// 64-bit FNV-1a; stable across platforms and runs (it names cache files and checks contents).
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
    /// columns); ByteReader::bytes reads them back.
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
    /// `describe(why)` makes the message of the Error thrown when the bytes do not hold what is
    /// read ("truncated", ...), e.g. naming the file and what to do about it.
    ByteReader(std::string_view bytes, std::function<std::string(std::string_view why)> describe)
        : mBytes(bytes), mDescribe(std::move(describe)) {}

    template <typename T>
    T pod() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        std::memcpy(&value, take(sizeof(T)), sizeof(T));
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
        const auto n = count(sizeof(T));
        std::vector<T> values(n);
        if (n != 0) std::memcpy(values.data(), take(n * sizeof(T)), n * sizeof(T));
        return values;
    }
    std::string string() {
        const auto n = count(1);
        return std::string(take(n), n);
    }
    /// `n` raw bytes.
    std::string_view bytes(std::size_t n) { return {take(n), n}; }

    std::size_t remaining() const { return mBytes.size() - mAt; }
    bool atEnd() const { return mAt == mBytes.size(); }
    [[noreturn]] void fail(std::string_view why) const;

private:
    const char* take(std::size_t n) {
        if (n > remaining()) fail("truncated");
        const char* p = mBytes.data() + mAt;
        mAt += n;
        return p;
    }

    std::string_view mBytes;
    std::size_t mAt = 0;
    std::function<std::string(std::string_view)> mDescribe;
};

}  // namespace modeflow
