#pragma once
/// @file SceneFixtures.h
/// The scene files tests share (tests/data/scenes/NAME.toml) and the one way a test varies
/// them: replacing text, usually one key's line, in a fixture's text.

#include <string>
#include <utility>
#include <vector>

namespace modeflow::testing {

/// The text of tests/data/scenes/`name`.toml; throws (failing the test) when there is none.
std::string sceneFixture(const std::string& name);

/// `text` with the first `from` replaced by `to`, e.g. replaced(scene, "[24, 24]", "[6, 6]").
/// A `from` that is not there fails the test: the variation would silently not be made.
std::string replaced(std::string text, const std::string& from, const std::string& to);

/// The same for several replacements, made in order.
std::string replaced(std::string text,
                     const std::vector<std::pair<std::string, std::string>>& replacements);

}  // namespace modeflow::testing
