#include "engine/format/InputFile.h"

#include <cerrno>
#include <fstream>
#include <system_error>

#include "engine/format/Error.h"

namespace modeflow {

std::uintmax_t regularFileSize(const std::filesystem::path& path, std::string_view what,
                               std::uintmax_t maxBytes) {
    const std::string named = std::string(what) + " " + path.string();
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status))
        throw Error("cannot read " + named + ": " + (ec ? ec.message() : "no such file"));
    if (std::filesystem::is_directory(status)) throw Error(named + " is a folder, not a file");
    if (!std::filesystem::is_regular_file(status))
        throw Error(named +
                    " is not a regular file (a FIFO, socket or device cannot be read as one)");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read " + named + ": " + ec.message());
    if (size > maxBytes)
        throw Error(named + " is " + std::to_string(size) + " bytes, more than the " +
                    std::to_string(maxBytes) + " a " + std::string(what) + " can be");
    return size;
}

std::string readRegularFile(const std::filesystem::path& path, std::string_view what,
                            std::uintmax_t maxBytes) {
    const std::uintmax_t size = regularFileSize(path, what, maxBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot open " + std::string(what) + " " + path.string() + ": " +
                    std::error_code(errno, std::generic_category()).message());
    // One byte more than measured shows a file that grew since: not the file that was checked.
    std::string bytes(size_t(size) + 1, '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (in.bad())
        throw Error("cannot read " + std::string(what) + " " + path.string() + ": " +
                    std::error_code(errno, std::generic_category()).message());
    bytes.resize(size_t(in.gcount()));
    if (bytes.size() > size)
        throw Error(std::string(what) + " " + path.string() +
                    " changed while it was read; try again");
    return bytes;
}

}  // namespace modeflow
