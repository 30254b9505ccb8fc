#include "engine/format/SmokeMaskFile.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/core/AtomicFile.h"
#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"

namespace modeflow {
namespace {

constexpr char kMagic[16] = {'M', 'O', 'D', 'E', 'F', 'L', 'O', 'W',
                             '-', 'M', 'A', 'S', 'K', 0,   0,   0};
constexpr std::uint32_t kVersion = 2;  ///< 2: XXH3 checksum

}  // namespace

std::filesystem::path smokeMaskPath(const std::filesystem::path& cachePath, int scale) {
    std::filesystem::path path = cachePath;
    path.replace_extension(".smoke" + std::to_string(scale) + ".mfmask");
    return path;
}

void writeSmokeMask(const std::filesystem::path& path, std::uint64_t keyHash, int scale,
                    const std::vector<std::uint8_t>& mask) {
    std::vector<std::uint8_t> bits((mask.size() + 7) / 8, 0);
    for (std::size_t c = 0; c < mask.size(); ++c)
        if (mask[c]) bits[c / 8] |= std::uint8_t(1u << (c % 8));
    ByteWriter w;
    w.pod(kMagic);
    w.pod(kVersion);
    w.pod(std::uint32_t(scale));
    w.pod(keyHash);
    w.pod(std::uint64_t(mask.size()));
    w.vector(bits);
    std::string bytes = w.bytes();
    const std::uint64_t checksum = checksum64(bytes);
    bytes.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    writeFileAtomically(path, bytes, "smoke mask");
}

std::vector<std::uint8_t> readSmokeMask(const std::filesystem::path& path, std::uint64_t keyHash,
                                        int scale, std::size_t cells) {
    const std::string where = "smoke mask " + path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw Error(where + " is missing");
    // The file's size follows from the cell count: anything else is refused before it is read.
    const std::uintmax_t expected = sizeof kMagic + 4 + 4 + 8 + 8 + 8 + (cells + 7) / 8 + 8;
    if (std::filesystem::file_size(path, ec) != expected)
        throw Error(where + " has the wrong size");
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (bytes.size() != expected) throw Error(where + " cannot be read");
    ByteReader r(bytes, [&](std::string_view why) { return where + " is " + std::string(why); });
    char magic[sizeof kMagic];
    r.read(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) r.fail("not a smoke mask (bad magic)");
    if (r.pod<std::uint32_t>() != kVersion) r.fail("of another format version");
    if (r.pod<std::uint32_t>() != std::uint32_t(scale) || r.pod<std::uint64_t>() != keyHash ||
        r.pod<std::uint64_t>() != cells)
        r.fail("made for another basis or smoke scale");
    const std::vector<std::uint8_t> bits = r.vector<std::uint8_t>();
    const std::uint64_t body = r.hash();
    if (r.pod<std::uint64_t>() != body) r.fail("damaged (checksum mismatch)");
    if (bits.size() != (cells + 7) / 8) r.fail("damaged (wrong bit count)");
    std::vector<std::uint8_t> mask(cells);
    for (std::size_t c = 0; c < cells; ++c) mask[c] = (bits[c / 8] >> (c % 8)) & 1u;
    return mask;
}

}  // namespace modeflow
