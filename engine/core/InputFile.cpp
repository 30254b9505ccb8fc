/// @file InputFile.cpp

#include "engine/core/InputFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "engine/core/Error.h"
#include "engine/core/FileKind.h"

namespace modeflow {
namespace {

/// `bytes` in the largest binary unit that holds it whole ("4 MiB", "64 GiB").
std::string sizeText(std::uintmax_t bytes) {
    for (const auto& [shift, unit] : {std::pair{30, " GiB"}, {20, " MiB"}, {10, " KiB"}})
        if (bytes >= (std::uintmax_t{1} << shift) && bytes % (std::uintmax_t{1} << shift) == 0)
            return std::to_string(bytes >> shift) + unit;
    return std::to_string(bytes) + " bytes";
}

/// "a scene file", "an input script".
std::string withArticle(std::string_view what) {
    const bool vowel =
        !what.empty() && std::string_view("aeiou").find(what.front()) != std::string_view::npos;
    return (vowel ? "an " : "a ") + std::string(what);
}

}  // namespace

std::string inputTooLarge(const std::string& name, std::uintmax_t bytes, std::string_view what,
                          std::uintmax_t maxBytes) {
    return name + ": " + std::to_string(bytes) + " bytes is too large for " + withArticle(what) +
           " (at most " + sizeText(maxBytes) + "); is it the right file?";
}

std::uintmax_t inputFileSize(const std::filesystem::path& path, std::string_view what,
                             std::uintmax_t maxBytes) {
    const std::string name = path.string();
    std::error_code ec;
    if (auto why = whyNotARegularFile(path)) {
        // "is a directory, not a scene file"; a path that cannot be reached says why.
        if (*why == "does not exist") throw Error(name + ": no such " + std::string(what));
        throw Error(name + ": " + *why +
                    (why->rfind("is ", 0) == 0 ? ", not " + withArticle(what) : ""));
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec)
        throw Error(name + ": cannot read the " + std::string(what) + " (" + ec.message() + ")");
    if (size > maxBytes) throw Error(inputTooLarge(name, size, what, maxBytes));
    return size;
}

std::string readInputFile(const std::filesystem::path& path, std::string_view what,
                          std::uintmax_t maxBytes) {
    const std::string name = path.string();
    inputFileSize(path, what, maxBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(name + ": cannot open the " + std::string(what) + " (" + std::strerror(errno) +
                    ")");
    // Read in pieces up to the limit: the file may have grown since its size was taken.
    std::string bytes;
    char piece[1 << 16];
    while (in.read(piece, sizeof piece) || in.gcount() > 0) {
        bytes.append(piece, static_cast<std::size_t>(in.gcount()));
        if (bytes.size() > maxBytes) throw Error(inputTooLarge(name, bytes.size(), what, maxBytes));
    }
    if (in.bad()) throw Error(name + ": error while reading the " + std::string(what));
    return bytes;
}

}  // namespace modeflow
