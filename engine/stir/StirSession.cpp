#include "engine/stir/StirSession.h"

#include <algorithm>
#include <cstdio>

#include "engine/core/Error.h"
#include "engine/core/SceneKeywords.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/stir/StrokeSplats.h"

namespace modeflow::stir {

Integrator otherIntegrator(Integrator integrator) {
    return integrator == Integrator::Midpoint ? Integrator::Explicit : Integrator::Midpoint;
}

double scaledViscosity(double viscosity, bool up, double highestKappaSquared, double dt) {
    // The first step: ν that damps the highest mode by 1/e in about 100 steps.
    const double first = highestKappaSquared > 0.0 ? 0.01 / (dt * highestKappaSquared) : 1e-4;
    return up ? (viscosity > 0.0 ? 2.0 * viscosity : first)
              : (viscosity > first ? 0.5 * viscosity : 0.0);
}

StirSession::StirSession(const Backend& backend, const RunInputs& run, StirSettings settings)
    : mBackend(backend),
      mRun(run),
      mSceneSettings(run.settings),
      mStir(settings),
      mBases(shapedBases(run.scene.basis)) {
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
    mDim = grid.dim;
    mBoxSize = 0.0;
    for (int a = 0; a < mDim; ++a) {
        mBoxSize = std::max(mBoxSize, grid.spacing[a] * grid.cells[a]);
        mPaddleAt[a] = grid.origin[a] + 0.5 * grid.spacing[a] * grid.cells[a];
    }
    mShapedRuns.resize(mBases.size() - 1);
    mSimulations.resize(mBases.size());
    mBasis = mBases.size() - 1;  // the scene's own basis, all of it
    simulationOf(mBasis);
}

Simulator& StirSession::simulationOf(std::size_t b) {
    if (!mSimulations[b]) {
        if (b + 1 == mBases.size()) {
            mSimulations[b] = mBackend.makeSimulator(mRun, true);
        } else {
            const int modes = mBases[b].modes;
            auto shaped = std::make_unique<RunInputs>();
            shaped->scene = mRun.scene;
            shaped->cachePath = mRun.cachePath;
            shaped->cache = leadingModes(mRun.cache, modes);
            shaped->coefficients = leadingCoefficients(*mRun.coefficients, modes);
            shaped->settings = mRun.settings;
            shaped->settings.fluid.kappaSquared = mRun.cache.velocity.eigenvalues.head(modes);
            shaped->smokeMask = mRun.smokeMask;
            shaped->initialVelocity = mRun.initialVelocity.head(modes);
            mSimulations[b] = mBackend.makeSimulator(*shaped, true);
            mShapedRuns[b] = std::move(shaped);
        }
    }
    return *mSimulations[b];
}

void StirSession::press(const Vec3& point) {
    mDragging = true;
    mPointer = mStrokeFrom = point;
    mStrokeTime = 0.0;
    // The paddle jumps to where the user grabs; from there on it moves with the pointer.
    if (mPaddleMode) mPaddleAt = point;
}

void StirSession::moveTo(const Vec3& point) {
    mPointer = point;
}

void StirSession::release() {
    mDragging = false;
}

void StirSession::reset() {
    const std::size_t cells = std::size_t(simulation().smokeGrid().cellCount());
    const SmokeFields empty{std::vector<double>(cells, 0.0), std::vector<double>(cells, 0.0)};
    Eigen::VectorXd v = Eigen::VectorXd::Zero(modeCount());
    const Eigen::Index shared = std::min<Eigen::Index>(v.size(), mRun.initialVelocity.size());
    v.head(shared) = mRun.initialVelocity.head(shared);
    current().restore(0.0, v, empty);
}

void StirSession::toggleIntegrator() {
    const Integrator next = otherIntegrator(settings().integrator);
    for (auto& simulation : mSimulations)
        if (simulation) simulation->setIntegrator(next);
    mSceneSettings.integrator = next;
}

void StirSession::scaleViscosity(bool up) {
    const double nu = scaledViscosity(settings().fluid.viscosity, up,
                                      mRun.cache.velocity.eigenvalues.maxCoeff(), settings().dt);
    for (auto& simulation : mSimulations)
        if (simulation) simulation->setViscosity(nu);
    mSceneSettings.fluid.viscosity = nu;
}

void StirSession::nextBasis() {
    if (mBases.size() < 2) return;
    const std::size_t next = (mBasis + 1) % mBases.size();
    Simulator& from = current();
    Simulator& to = simulationOf(next);
    to.setIntegrator(mSceneSettings.integrator);
    to.setViscosity(mSceneSettings.fluid.viscosity);
    // The leading modes are the same functions in both bases: they carry over, the rest start
    // (or stay) at rest.
    const Eigen::VectorXd v = from.velocity();
    Eigen::VectorXd carried = Eigen::VectorXd::Zero(mBases[next].modes);
    const Eigen::Index shared = std::min<Eigen::Index>(v.size(), carried.size());
    carried.head(shared) = v.head(shared);
    to.restore(from.time(), carried, from.smoke());
    mBasis = next;
}

void StirSession::togglePaddle() {
    mPaddleMode = !mPaddleMode;
    if (!mPaddleMode) current().setObstacles(mSceneSettings.obstacles);
}

std::optional<PaddlePose> StirSession::paddle() const {
    if (!mPaddleMode) return std::nullopt;
    PaddlePose pose;
    pose.centre = mPaddleAt;
    pose.axis[mDim == 2 ? 1 : 2] = mStir.paddleLength * mBoxSize;
    pose.radius = mStir.paddleRadius * mBoxSize;
    return pose;
}

std::vector<ForceSplat> StirSession::strokeSplats(double elapsed) const {
    if (!mDragging || mPaddleMode) return {};
    return stir::strokeSplats(mStrokeFrom, mPointer, elapsed, mStir.splatRadius * mBoxSize,
                              mStir.force);
}

MovingObstacle StirSession::paddleObstacle(int steps) const {
    const PaddlePose pose = *paddle();
    MovingObstacle obstacle;
    obstacle.spec.shape = ObstacleShape::Capsule;
    obstacle.spec.radius = pose.radius;
    obstacle.spec.axis = pose.axis;
    // From where it was to the pointer over these steps, in the simulation's time, and on at
    // that velocity past the last step's end, so the last step still sees it moving.
    const double dt = settings().dt, t0 = simulation().time();
    const Vec3 to = mDragging ? mPointer : mPaddleAt;
    Vec3 beyond{};
    for (int a = 0; a < 3; ++a)
        beyond[a] = mPaddleAt[a] + (to[a] - mPaddleAt[a]) * (steps + 1.0) / steps;
    obstacle.spec.path = {{t0, mPaddleAt}, {t0 + (steps + 1) * dt, beyond}};
    return obstacle;
}

FrameStats StirSession::advance(int steps, double elapsed) {
    mStrokeTime += elapsed;
    if (steps < 1) return {};
    Simulator& simulation = current();
    const std::vector<ForceSplat> splats = strokeSplats(mStrokeTime);
    simulation.setSplats(splats);
    if (mPaddleMode) {
        std::vector<MovingObstacle> obstacles = mSceneSettings.obstacles;
        obstacles.push_back(paddleObstacle(steps));
        simulation.setObstacles(std::move(obstacles));
        if (mDragging) mPaddleAt = mPointer;
    }
    simulation.setTiming(mTiming);
    const FrameStats stats = simulation.advanceSteps(steps);
    mStrokeFrom = mPointer;
    mStrokeTime = 0.0;
    return stats;
}

double StirSession::energy() const {
    return modeflow::energy(simulation().velocity());
}

std::string StirSession::status() const {
    char line[200];
    std::snprintf(line, sizeof line, "%s | viscosity %.3g | %d modes (%s) | mouse: %s",
                  std::string(sceneKeyword(settings().integrator)).c_str(),
                  settings().fluid.viscosity, modeCount(), mBases[mBasis].label.c_str(),
                  mPaddleMode ? "paddle" : "stir");
    return line;
}

}  // namespace modeflow::stir
