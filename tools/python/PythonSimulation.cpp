#include "tools/python/PythonSimulation.h"

#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/run/GridFrames.h"
#include "engine/simulation/WindTransport.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/compose/Preflight.h"
#include "tools/compose/RunIdentity.h"
#include "tools/compose/RunPreparation.h"
#include "tools/python/PythonProgress.h"

namespace py = pybind11;

namespace modeflow::python {
namespace {

/// Shape (nx, ny[, nz][, extra]) with x varying fastest in memory, as the engine stores cells:
/// a Fortran-ordered array whose first index is x.
py::array_t<double> cellArray(const MacGrid& grid, int components) {
    std::vector<py::ssize_t> shape, strides;
    py::ssize_t stride = sizeof(double) * components;
    for (int a = 0; a < grid.dim; ++a) {
        shape.push_back(grid.cells[a]);
        strides.push_back(stride);
        stride *= grid.cells[a];
    }
    if (components > 1) {
        shape.push_back(components);
        strides.push_back(sizeof(double));
    }
    return py::array_t<double>(shape, strides);
}

py::array_t<double> cellValues(const MacGrid& grid, const std::vector<double>& values) {
    py::array_t<double> out = cellArray(grid, 1);
    std::copy(values.begin(), values.end(), out.mutable_data());
    return out;
}

Vec3 vectorArgument(const std::vector<double>& value, int dim, const char* what) {
    if (int(value.size()) != dim && !(dim == 2 && value.size() == 3))
        throw Error(std::string(what) + ": expected " + std::to_string(dim) + " numbers, got " +
                    std::to_string(value.size()));
    Vec3 v{0.0, 0.0, 0.0};
    for (std::size_t a = 0; a < value.size(); ++a) {
        if (!std::isfinite(value[a]))
            throw Error(std::string(what) + ": " + std::to_string(value[a]) + " is not finite");
        v[a] = value[a];
    }
    return v;
}

/// A rotation key turning the shape by `orientation` at `time`.
RotationKey rotationKey(double time, const Eigen::Matrix3d& orientation) {
    const Eigen::AngleAxisd turn(orientation);
    return {time, {turn.axis().x(), turn.axis().y(), turn.axis().z()}, turn.angle() * 180.0 / M_PI};
}

std::size_t checkedIndex(int index, std::size_t count, const char* what, const char* thing) {
    if (index < 0 || std::size_t(index) >= count)
        throw Error(std::string(what) + ": no " + thing + " " + std::to_string(index) +
                    " (the scene has " + std::to_string(count) + ")");
    return std::size_t(index);
}

/// `rotation` as [x, y, z, degrees] (a rotation key's turn); none: keep the orientation.
std::optional<Eigen::Matrix3d> rotationArgument(const std::optional<std::vector<double>>& rotation,
                                                const char* what) {
    if (!rotation) return std::nullopt;
    const std::string name = std::string(what) + ": rotation";
    if (rotation->size() != 4)
        throw Error(name + ": expected [x, y, z, degrees], got " +
                    std::to_string(rotation->size()) + " numbers");
    const Vec3 axis =
        vectorArgument({(*rotation)[0], (*rotation)[1], (*rotation)[2]}, 3, name.c_str());
    const Eigen::Vector3d a(axis[0], axis[1], axis[2]);
    const double degrees = (*rotation)[3];
    if (!(a.norm() > 0.0) || !std::isfinite(degrees))
        throw Error(name + ": a non-zero axis and a finite angle");
    return Eigen::AngleAxisd(degrees * M_PI / 180.0, a.normalized()).toRotationMatrix();
}

struct KeyedMotion {
    std::vector<std::pair<double, Vec3>> path;
    std::vector<RotationKey> rotation;
};

/// Key frames at t and t + 2 dt through the pose (`target`, `turned`) at t + dt, from the pose
/// now: a path's velocity is that of the segment holding the time, and a step's solids and
/// sources stand where they are at its end (t + dt), where a segment ending there would say 0.
KeyedMotion motionThrough(const Vec3& now, const Eigen::Matrix3d& from, double t, double dt,
                          const Vec3& target, const std::optional<Eigen::Matrix3d>& turned) {
    Vec3 beyond;
    for (int a = 0; a < 3; ++a) beyond[a] = 2.0 * target[a] - now[a];
    KeyedMotion motion{{{t, now}, {t + 2.0 * dt, beyond}}, {rotationKey(t, from)}};
    if (turned)
        motion.rotation.push_back(rotationKey(t + 2.0 * dt, *turned * from.transpose() * *turned));
    return motion;
}

}  // namespace

PythonSimulation::PythonSimulation(const SceneText& scene, const std::string& device,
                                   const std::optional<std::string>& cacheDir,
                                   const py::object& progress) {
    if (scene.spec.isSurface())
        throw Error(scene.spec.name +
                    ": surface scenes are run with `modeflow run` (modeflow.Simulation steps "
                    "grid scenes)");
    const Preflight checked = preflight(scene.spec, device, RunParts::DynamicsAndSmoke);
    mSceneHash = runIdentity(checked.scene, checked.backend.kind, scene.text).sceneHash;
    const std::filesystem::path cache = resolveCacheDir(cacheDir);
    PythonProgress report(progress);
    py::gil_scoped_release released;
    mBackend = std::make_unique<Backend>(checked.backend);
    mBackend->requireFits(checked.scene);
    mRun = std::make_unique<RunInputs>(prepareRun(checked.scene, cache, report.progress()));
    mSimulator = mBackend->makeSimulator(*mRun);
    mBasisGrid = airGridOf(mRun->cache.grid, mRun->settings.wind);
    mObstacles = mSimulator->settings().obstacles;
    mSources = mSimulator->settings().emitters;
}

void PythonSimulation::step(int steps) {
    if (steps < 0) throw Error("step: " + std::to_string(steps) + " steps (at least 0)");
    mSimulator->setSplats(mSplats);
    for (int s = 0; s < steps; ++s) {
        {
            py::gil_scoped_release released;
            mSimulator->advanceSteps(1);
        }
        ++mSteps;
        if (PyErr_CheckSignals() != 0) {
            mSplats.clear();
            mSimulator->setSplats(mSplats);
            throw py::error_already_set();
        }
    }
    mSplats.clear();
    mSimulator->setSplats(mSplats);
}

double PythonSimulation::energy() const {
    return modeflow::energy(mSimulator->velocity());
}

py::array_t<double> PythonSimulation::modalVelocity() const {
    const Eigen::VectorXd v = mSimulator->velocity();
    return py::array_t<double>(v.size(), v.data());
}

py::array_t<double> PythonSimulation::density() const {
    return cellValues(mSimulator->smokeGrid(), mSimulator->smoke().density);
}

py::array_t<double> PythonSimulation::temperature() const {
    return cellValues(mSimulator->smokeGrid(), mSimulator->smoke().temperature);
}

std::optional<py::array_t<double>> PythonSimulation::fuel() const {
    if (!mSimulator->settings().fire) return std::nullopt;
    return cellValues(mSimulator->smokeGrid(), mSimulator->smoke().fuel);
}

std::optional<py::array_t<double>> PythonSimulation::flame() const {
    if (!mSimulator->settings().fire) return std::nullopt;
    return cellValues(mSimulator->smokeGrid(), mSimulator->smoke().flame);
}

py::array_t<double> PythonSimulation::velocity() const {
    const MacGrid& smoke = mSimulator->smokeGrid();
    const std::vector<double> faces = mSimulator->faceVelocity();
    py::array_t<double> out = cellArray(smoke, smoke.dim);
    double* value = out.mutable_data();
    for (int k = 0; k < smoke.cells[2]; ++k)
        for (int j = 0; j < smoke.cells[1]; ++j)
            for (int i = 0; i < smoke.cells[0]; ++i) {
                const Vec3 centre{smoke.cellCentre(0, i), smoke.cellCentre(1, j),
                                  smoke.dim == 3 ? smoke.cellCentre(2, k) : 0.5};
                const Vec3 u = sampleVelocity(mBasisGrid, std::span<const double>(faces), centre);
                for (int a = 0; a < smoke.dim; ++a) *value++ = u[a];
            }
    return out;
}

void PythonSimulation::addSplat(const std::vector<double>& centre, double radius,
                                const std::vector<double>& force) {
    const int dim = mSimulator->smokeGrid().dim;
    if (!(radius > 0.0) || !std::isfinite(radius))
        throw Error("add_splat: radius " + std::to_string(radius) + " (a positive number)");
    mSplats.push_back({vectorArgument(centre, dim, "add_splat: center"),
                       vectorArgument(force, dim, "add_splat: force"), radius});
}

void PythonSimulation::setObstaclePose(int index, const std::vector<double>& position,
                                       const std::optional<std::vector<double>>& rotation) {
    const char* what = "set_obstacle_pose";
    MovingObstacle& solid = mObstacles[checkedIndex(index, mObstacles.size(), what, "obstacle")];
    const double t = mSimulator->time();
    const KeyedMotion motion =
        motionThrough(solid.centreAt(t), solid.orientationAt(t), t, mSimulator->settings().dt,
                      vectorArgument(position, mSimulator->smokeGrid().dim, what),
                      rotationArgument(rotation, what));
    solid.spec.path = motion.path;
    solid.spec.rotation = motion.rotation;
    mSimulator->setObstacles(mObstacles);
}

void PythonSimulation::setSourcePose(int index, const std::vector<double>& position,
                                     const std::optional<std::vector<double>>& rotation) {
    const char* what = "set_source_pose";
    SmokeEmitter& source = mSources[checkedIndex(index, mSources.size(), what, "source")];
    const double t = mSimulator->time();
    const SmokeEmitter now = source.placedAt(t);
    const KeyedMotion motion = motionThrough(
        now.placement ? now.placement->centre : now.restCentre(),
        now.placement ? now.placement->orientation : Eigen::Matrix3d::Identity(), t,
        mSimulator->settings().dt, vectorArgument(position, mSimulator->smokeGrid().dim, what),
        rotationArgument(rotation, what));
    source.path = motion.path;
    source.rotation = motion.rotation;
    mSimulator->setEmitters(mSources);
}

void PythonSimulation::writeVdb(const std::filesystem::path& file) const {
    const SmokeFields smoke = mSimulator->smoke();
    const std::vector<double> faceVelocity = mSimulator->faceVelocity();
    const std::vector<double> faceMagnetic = mSimulator->faceMagneticField();
    writeVdbFrame(file, gridVdbFrame(*mSimulator, mRun->smokeMask, mBasisGrid, smoke, faceVelocity,
                                     faceMagnetic, int(frame()), mSceneHash, false));
}

}  // namespace modeflow::python
