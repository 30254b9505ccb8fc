#include "tools/compose/CacheDirectory.h"

#include <cstdlib>

#include "engine/core/Error.h"

namespace modeflow {

std::filesystem::path resolveCacheDir(const std::optional<std::string>& option) {
    if (option) return *option;
    auto env = [](const char* name) -> std::optional<std::string> {
        const char* v = std::getenv(name);
        if (v && *v) return std::string(v);
        return std::nullopt;
    };
    if (auto dir = env("MODEFLOW_CACHE_DIR")) return *dir;
    if (auto xdg = env("XDG_CACHE_HOME")) return std::filesystem::path(*xdg) / "modeflow";
    if (auto home = env("HOME")) return std::filesystem::path(*home) / ".cache" / "modeflow";
    throw Error("no cache directory: name one (--cache-dir, cache_dir=) or set MODEFLOW_CACHE_DIR");
}

}  // namespace modeflow
