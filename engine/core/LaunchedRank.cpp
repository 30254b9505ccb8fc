#include "engine/core/LaunchedRank.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

namespace modeflow {
namespace {

std::optional<int> number(const char* name) {
    const char* text = std::getenv(name);
    if (text == nullptr) return std::nullopt;
    try {
        std::size_t used = 0;
        const int value = std::stoi(text, &used);
        if (used == std::string(text).size() && value >= 0) return value;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

}  // namespace

LaunchedRank launchedRank() {
    // Rank and size variables of each launcher; PMIx gives the rank alone.
    const char* kinds[][2] = {{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                              {"PMI_RANK", "PMI_SIZE"},
                              {"PMIX_RANK", "SLURM_STEP_NUM_TASKS"}};
    for (const auto& [rankName, sizeName] : kinds) {
        const bool present = std::getenv(rankName) != nullptr || std::getenv(sizeName) != nullptr;
        if (!present) continue;
        LaunchedRank place;
        place.launched = true;
        place.rank = number(rankName).value_or(0);
        place.size = std::max(number(sizeName).value_or(1), place.rank + 1);
        return place;
    }
    return {};
}

}  // namespace modeflow
