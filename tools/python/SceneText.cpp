#include "tools/python/SceneText.h"

#include <memory>
#include <sstream>
#include <utility>

#include <toml++/toml.h>

#include "engine/core/Error.h"
#include "engine/core/InputFile.h"
#include "precompute/scene/SceneLoader.h"

namespace py = pybind11;

namespace modeflow::python {
namespace {

/// A Python value as a TOML node; `key` names it in errors ("obstacle[0].path").
std::unique_ptr<toml::node> tomlNode(const py::handle& value, const std::string& key);

toml::table tomlTable(const py::dict& values, const std::string& key) {
    toml::table table;
    for (const auto& [name, value] : values) {
        if (!py::isinstance<py::str>(name))
            throw Error("from_dict: " + (key.empty() ? std::string("a") : key + ": a") +
                        " key is not a string (" + py::str(py::repr(name)).cast<std::string>() +
                        ")");
        const std::string child = name.cast<std::string>();
        const std::string path = key.empty() ? child : key + "." + child;
        const std::unique_ptr<toml::node> node = tomlNode(value, path);
        table.insert(child, std::move(*node));
    }
    return table;
}

std::unique_ptr<toml::node> tomlNode(const py::handle& value, const std::string& key) {
    // bool before int: Python's bool is an int.
    if (py::isinstance<py::bool_>(value))
        return std::make_unique<toml::value<bool>>(value.cast<bool>());
    if (py::isinstance<py::str>(value))
        return std::make_unique<toml::value<std::string>>(value.cast<std::string>());
    if (py::isinstance<py::dict>(value))
        return std::make_unique<toml::table>(tomlTable(value.cast<py::dict>(), key));
    const py::module_ numbers = py::module_::import("numbers");
    if (py::isinstance(value, numbers.attr("Integral"))) {
        const py::int_ integer(py::reinterpret_borrow<py::object>(value));
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(integer.ptr(), &overflow);
        if (overflow != 0)
            throw Error("from_dict: " + key + ": " + py::repr(integer).cast<std::string>() +
                        " does not fit TOML's 64-bit integers");
        return std::make_unique<toml::value<std::int64_t>>(std::int64_t(v));
    }
    if (py::isinstance(value, numbers.attr("Real"))) {
        const double v = PyFloat_AsDouble(value.ptr());
        if (v == -1.0 && PyErr_Occurred()) throw py::error_already_set();
        return std::make_unique<toml::value<double>>(v);
    }
    if (py::isinstance<py::sequence>(value)) {
        toml::array array;
        std::size_t index = 0;
        for (const py::handle item : value.cast<py::sequence>()) {
            const std::unique_ptr<toml::node> node =
                tomlNode(item, key + "[" + std::to_string(index++) + "]");
            array.push_back(std::move(*node));
        }
        return std::make_unique<toml::array>(std::move(array));
    }
    throw Error("from_dict: " + key + ": TOML holds no " +
                py::str(value.get_type().attr("__name__")).cast<std::string>() + " (" +
                py::str(py::repr(value)).cast<std::string>() + ")");
}

}  // namespace

SceneText loadSceneText(const std::filesystem::path& file) {
    // loadScene's reading, keeping the text.
    return sceneFromToml(readInputFile(file, "scene file", kMaxSceneFileBytes), file);
}

SceneText sceneFromToml(std::string text, const std::filesystem::path& origin) {
    SceneSpec spec = parseScene(text, origin);
    return {std::move(spec), std::move(text)};
}

SceneText sceneFromDict(const py::dict& scene, const std::filesystem::path& origin) {
    std::ostringstream text;
    text << toml::toml_formatter(tomlTable(scene, ""));
    return sceneFromToml(text.str(), origin);
}

}  // namespace modeflow::python
