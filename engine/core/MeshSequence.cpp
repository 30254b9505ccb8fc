#include "engine/core/MeshSequence.h"

#include <string>
#include <system_error>

namespace modeflow {

bool isMeshSequence(const std::filesystem::path& pattern) {
    return pattern.filename().string().find('#') != std::string::npos;
}

std::filesystem::path sequenceFile(const std::filesystem::path& pattern, int number) {
    std::string name = pattern.filename().string();
    const std::size_t last = name.rfind('#');
    if (last == std::string::npos) return pattern;
    std::size_t first = last;
    while (first > 0 && name[first - 1] == '#') --first;
    std::string digits = std::to_string(number);
    const std::size_t width = last - first + 1;
    if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
    name.replace(first, width, digits);
    return pattern.parent_path() / name;
}

int sequenceLength(const std::filesystem::path& pattern, int limit) {
    int count = 0;
    std::error_code ec;
    while (count < limit && std::filesystem::is_regular_file(sequenceFile(pattern, count + 1), ec))
        ++count;
    return count;
}

}  // namespace modeflow
