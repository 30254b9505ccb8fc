/// The `modeflow` Python module's native part, `modeflow._modeflow` (tools/python/README.md):
/// Scene, Simulation, inspect and Error. modeflow::Error becomes modeflow.Error carrying the
/// message the CLI prints after "modeflow: error: ".

#include <filesystem>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "engine/core/Error.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/compose/CacheSummary.h"
#include "tools/python/PythonProgress.h"
#include "tools/python/PythonSimulation.h"
#include "tools/python/SceneText.h"

namespace py = pybind11;
using modeflow::python::PythonSimulation;
using modeflow::python::SceneText;

namespace {

/// "cpu", "vulkan", or a device index given as an int or a str.
std::string deviceOption(const py::object& device) {
    if (py::isinstance<py::bool_>(device) ||
        !(py::isinstance<py::int_>(device) || py::isinstance<py::str>(device)))
        throw modeflow::Error("device: expected \"cpu\", \"vulkan\" or a device index, got " +
                              py::str(py::repr(device)).cast<std::string>());
    return py::str(device).cast<std::string>();
}

std::filesystem::path originOf(const std::string& name,
                               const std::optional<std::filesystem::path>& folder) {
    const std::filesystem::path file = name + ".toml";
    return folder ? *folder / file : file;
}

py::object inspect(const py::object& target, const std::optional<std::string>& cacheDir,
                   const py::object& progress) {
    const std::filesystem::path dir = modeflow::resolveCacheDir(cacheDir);
    modeflow::python::PythonProgress report(progress);
    std::string json;
    if (py::isinstance<SceneText>(target)) {
        const SceneText& scene = target.cast<const SceneText&>();
        py::gil_scoped_release released;
        json =
            modeflow::cacheSummary(modeflow::sceneCache(scene.spec, dir, report.progress())).dump();
    } else {
        const std::filesystem::path path = target.cast<std::filesystem::path>();
        py::gil_scoped_release released;
        json =
            modeflow::cacheSummary(modeflow::inspectedCache(path, dir, report.progress())).dump();
    }
    return py::module_::import("json").attr("loads")(json);
}

}  // namespace

PYBIND11_MODULE(_modeflow, m) {
    m.doc() = "modeflow: model-reduced fluid simulation (scenes, simulations, caches)";
    py::register_exception<modeflow::Error>(m, "Error", PyExc_RuntimeError);

    py::class_<SceneText>(m, "Scene", "A scene, read and checked as the command line reads it.")
        .def_static("load", &modeflow::python::loadSceneText, py::arg("path"),
                    "Reads a scene file (TOML).")
        .def_static(
            "from_toml",
            [](std::string text, const std::string& name,
               const std::optional<std::filesystem::path>& folder) {
                return modeflow::python::sceneFromToml(std::move(text), originOf(name, folder));
            },
            py::arg("text"), py::arg("name") = "scene", py::arg("folder") = py::none(),
            "A scene from TOML text; `name` names it (frames NAME_0001.vdb) and messages, "
            "relative mesh paths are read from `folder` (default: the current folder).")
        .def_static(
            "from_dict",
            [](const py::dict& scene, const std::string& name,
               const std::optional<std::filesystem::path>& folder) {
                return modeflow::python::sceneFromDict(scene, originOf(name, folder));
            },
            py::arg("scene"), py::arg("name") = "scene", py::arg("folder") = py::none(),
            "A scene from the TOML schema as nested dicts and lists, e.g. "
            "{'grid': {'resolution': [32, 32]}, 'basis': {'velocity_modes': 64}}.")
        .def_property_readonly("name", [](const SceneText& s) { return s.spec.name; })
        .def_property_readonly("dim", [](const SceneText& s) { return s.spec.grid.dim; })
        .def_property_readonly(
            "toml", [](const SceneText& s) { return s.text; }, "The scene's TOML text.")
        .def("__repr__",
             [](const SceneText& s) { return "<modeflow.Scene '" + s.spec.name + "'>"; });

    py::class_<PythonSimulation>(m, "Simulation",
                                 "A grid scene advancing step by step (precomputed on a cache "
                                 "miss, as `modeflow run`).")
        .def(py::init([](const SceneText& scene, const py::object& device,
                         const std::optional<std::string>& cacheDir, const py::object& progress) {
                 return std::make_unique<PythonSimulation>(scene, deviceOption(device), cacheDir,
                                                           progress);
             }),
             py::arg("scene"), py::arg("device") = "vulkan", py::arg("cache_dir") = py::none(),
             py::arg("progress") = py::none())
        .def("step", &PythonSimulation::step, py::arg("n") = 1,
             "Advances n steps (Ctrl-C stops between two).")
        .def_property_readonly("time", &PythonSimulation::time)
        .def_property_readonly("dt", [](const PythonSimulation& s) { return s.settings().dt; })
        .def_property_readonly("steps_per_frame",
                               [](const PythonSimulation& s) { return s.settings().stepsPerFrame; })
        .def_property_readonly("steps", &PythonSimulation::steps)
        .def_property_readonly("frame", &PythonSimulation::frame)
        .def_property_readonly("energy", &PythonSimulation::energy)
        .def_property_readonly("modal_velocity", &PythonSimulation::modalVelocity)
        .def_property_readonly("density", &PythonSimulation::density)
        .def_property_readonly("temperature", &PythonSimulation::temperature)
        .def_property_readonly("fuel", &PythonSimulation::fuel,
                               "The fuel per smoke cell with [fire], else None.")
        .def_property_readonly("flame", &PythonSimulation::flame,
                               "Fuel burned per unit time per smoke cell with [fire], else None.")
        .def_property_readonly("velocity", &PythonSimulation::velocity)
        .def("add_splat", &PythonSimulation::addSplat, py::arg("center"), py::arg("radius"),
             py::arg("force"))
        .def("set_obstacle_pose", &PythonSimulation::setObstaclePose, py::arg("index"),
             py::arg("position"), py::arg("rotation") = py::none())
        .def("set_source_pose", &PythonSimulation::setSourcePose, py::arg("index"),
             py::arg("position"), py::arg("rotation") = py::none())
        .def("write_vdb", &PythonSimulation::writeVdb, py::arg("path"));

    m.def("inspect", &inspect, py::arg("scene_or_cache"), py::arg("cache_dir") = py::none(),
          py::arg("progress") = py::none(),
          "What `modeflow inspect --json` prints, as a dict, for a cache file, a scene file or "
          "a Scene (its cache, precomputed on a miss).");
}
