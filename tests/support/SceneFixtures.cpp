#include "tests/support/SceneFixtures.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace modeflow::testing {

std::string sceneFixture(const std::string& name) {
    // Inside the repository only: the tests read nothing from elsewhere.
    const std::filesystem::path file =
        std::filesystem::path(MODEFLOW_SOURCE_DIR) / "tests" / "data" / "scenes" / (name + ".toml");
    std::ifstream in(file);
    if (!in) throw std::runtime_error("no scene fixture " + file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos)
        ADD_FAILURE() << "no '" << from << "' in the scene";
    else
        text.replace(at, from.size(), to);
    return text;
}

std::string replaced(std::string text,
                     const std::vector<std::pair<std::string, std::string>>& replacements) {
    for (const auto& [from, to] : replacements) text = replaced(std::move(text), from, to);
    return text;
}

}  // namespace modeflow::testing
