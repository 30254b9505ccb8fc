#pragma once
/// @file SceneText.h
/// A scene as the Python module holds it: the values the loader read and the TOML text they came
/// from (the frames' scene hash is that text's, as the CLI's is its file's).

#include <filesystem>
#include <string>

#include <pybind11/pybind11.h>

#include "engine/core/SceneSpec.h"

namespace modeflow::python {

struct SceneText {
    SceneSpec spec;
    std::string text;
};

/// Scene.load: the file, read and checked as the CLI reads it.
/// @throw modeflow::Error with the CLI's message.
SceneText loadSceneText(const std::filesystem::path& file);

/// Scene.from_toml: `origin` names the scene in messages, gives its name (the stem) and resolves
/// relative mesh paths against its folder.
SceneText sceneFromToml(std::string text, const std::filesystem::path& origin);

/// Scene.from_dict: the TOML schema as nested dicts (tables), lists (arrays; a list of dicts is
/// an array of tables such as [[obstacle]]), str, bool, int and float, written as TOML by toml++
/// and read by the same loader, so the checks and messages are the CLI's.
/// @throw modeflow::Error naming the key whose value TOML cannot hold.
SceneText sceneFromDict(const pybind11::dict& scene, const std::filesystem::path& origin);

}  // namespace modeflow::python
