#pragma once
/// @file PythonSimulation.h
/// modeflow.Simulation: a grid scene run step by step from Python, on the CPU reference or a
/// Vulkan device, through the engine's run API (Backend, Simulator) as `modeflow run` drives it,
/// after the same preflight and preparation (tools/compose).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "engine/core/MacGrid.h"
#include "engine/run/Backend.h"
#include "engine/run/RunInputs.h"
#include "engine/simulation/ForceSplat.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/Simulator.h"
#include "engine/simulation/SmokeEmitter.h"
#include "tools/python/SceneText.h"

namespace modeflow::python {

class PythonSimulation {
public:
    /// `device`: "cpu", "vulkan" or a device index (int or str), as `--device`.
    /// `progress`: called with each line of the preparation's report (precompute stages).
    /// @throw modeflow::Error with the CLI's message for what it refuses.
    PythonSimulation(const SceneText& scene, const std::string& device,
                     const std::optional<std::string>& cacheDir, const pybind11::object& progress);

    /// `steps` steps with the GIL released, checking for Ctrl-C after each; the splats added
    /// since the last call act on all of them and are dropped after.
    void step(int steps);

    double time() const { return mSimulator->time(); }
    long long steps() const { return mSteps; }
    /// Whole frames done ([simulation] steps per frame).
    long long frame() const { return mSteps / mSimulator->settings().stepsPerFrame; }
    /// Kinetic energy ½|v|² of the modal velocity.
    double energy() const;
    pybind11::array_t<double> modalVelocity() const;
    /// One value per smoke cell, indexed [i, j] or [i, j, k] (x first: the VDB's ijk).
    pybind11::array_t<double> density() const;
    pybind11::array_t<double> temperature() const;
    /// With [fire], the fuel and the flame (fuel burned per unit time) as density(); without,
    /// None.
    std::optional<pybind11::array_t<double>> fuel() const;
    std::optional<pybind11::array_t<double>> flame() const;
    /// The velocity at the smoke cell centres (as the VDB's `vel`), the last axis the component.
    pybind11::array_t<double> velocity() const;

    /// A Gaussian stirring force (ForceSplat) for the next step() call.
    void addSplat(const std::vector<double>& centre, double radius,
                  const std::vector<double>& force);
    /// Obstacle `index` ([[obstacle]] order) reaches `position` (and the orientation `rotation`:
    /// axis x, y, z and degrees, as a rotation key) at the end of the next step, moving and
    /// turning uniformly; it keeps that motion one step more unless set again, then holds. Its
    /// key frames no longer drive it.
    void setObstaclePose(int index, const std::vector<double>& position,
                         const std::optional<std::vector<double>>& rotation);
    /// The same for source `index` ([[source]] order).
    void setSourcePose(int index, const std::vector<double>& position,
                       const std::optional<std::vector<double>>& rotation);
    /// The frame now as `modeflow run` writes it (engine/output/VdbFrame.h).
    void writeVdb(const std::filesystem::path& file) const;

    const SimulationSettings& settings() const { return mSimulator->settings(); }

private:
    std::string mSceneHash;
    std::unique_ptr<Backend> mBackend;
    std::unique_ptr<RunInputs> mRun;  // the simulator keeps references into it
    std::unique_ptr<Simulator> mSimulator;
    MacGrid mBasisGrid;
    std::vector<ForceSplat> mSplats;
    std::vector<MovingObstacle> mObstacles;
    std::vector<SmokeEmitter> mSources;
    long long mSteps = 0;
};

}  // namespace modeflow::python
