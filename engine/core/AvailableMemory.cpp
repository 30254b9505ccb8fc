#include "engine/core/AvailableMemory.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "engine/core/NumberText.h"

namespace modeflow {
namespace {

constexpr const char* kLimitVariable = "MODEFLOW_MEMORY_LIMIT";

std::optional<std::uint64_t> memAvailable() {
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string key, unit;
        std::uint64_t kib = 0;
        if (fields >> key >> kib >> unit && key == "MemAvailable:" && unit == "kB")
            return kib * 1024;
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> availableMemory() {
    const char* limit = std::getenv(kLimitVariable);
    if (limit == nullptr) return memAvailable();
    char* end = nullptr;
    const unsigned long long bytes = std::strtoull(limit, &end, 10);
    if (end == limit || *end != '\0' || bytes == 0 || limit[0] == '-')
        throw Error(std::string(kLimitVariable) + " = \"" + limit +
                    "\": expected a positive whole number of bytes");
    return bytes;
}

std::string memoryText(double bytes) {
    const double kib = bytes / 1024.0, mib = kib / 1024.0, gib = mib / 1024.0;
    if (gib >= 1024.0) return numberText(gib / 1024.0) + " TiB";
    if (gib >= 1.0) return numberText(gib) + " GiB";
    if (mib >= 1.0) return numberText(mib) + " MiB";
    return kib >= 1.0 ? numberText(kib) + " KiB" : numberText(bytes) + " bytes";
}

void requireMemory(double estimateBytes, const std::string& subject, const std::string& what,
                   const std::string& advice) {
    const std::optional<std::uint64_t> available = availableMemory();
    if (!available || estimateBytes <= double(*available)) return;
    const std::string source = std::getenv(kLimitVariable) ? kLimitVariable : "MemAvailable";
    throw Error(subject + ": " + what + " needs about " + memoryText(estimateBytes) +
                " (estimate), but only " + memoryText(double(*available)) + " are available (" +
                source + "); " + advice);
}

Error outOfMemoryIn(const std::string& stage, double estimateBytes, const std::string& advice) {
    return Error("out of memory in " + stage + " (the estimated peak was " +
                 memoryText(estimateBytes) + "); " + advice);
}

}  // namespace modeflow
