#pragma once
/// @file StirSession.h
/// What `modeflow stir` does to the fluid, apart from any window: a Simulation of the scene on
/// the device, and the user's hand in it. A left drag either stirs, with force splats along the
/// pointer's path proportional to its speed (projected on the basis like buoyancy,
/// engine/README.md, "Reduced dynamics"), or moves a solid paddle, a moving obstacle that follows
/// the pointer (seed §6.3.5). Keys switch the integrator, scale the viscosity, reset, and switch
/// between the shaped bases the cache holds (ShapedBases.h), carrying the velocity's shared modes
/// and the smoke across.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/ShapedBases.h"
#include "engine/run/Backend.h"
#include "engine/run/RunInputs.h"

namespace modeflow::stir {

struct StirSettings {
    double force = 12.0;          ///< stirring acceleration per unit pointer speed (1/s)
    double splatRadius = 0.06;    ///< of the box's largest side
    double paddleRadius = 0.035;  ///< of the box's largest side
    double paddleLength = 0.12;   ///< half the paddle's segment, of the box's largest side
};

/// The paddle where it is now, for drawing.
struct PaddlePose {
    Vec3 centre{};
    Vec3 axis{};  ///< from the centre to one end of the segment
    double radius = 0.0;
};

/// The integrator the integrator key switches to: implicit midpoint ↔ explicit Euler.
Integrator otherIntegrator(Integrator integrator);
/// The viscosity keys: ν × 2 (`up`), or ÷ 2; the first step up from 0 damps the highest mode
/// (κ² = highestKappaSquared) by 1/e in about 100 steps of dt, and a step down from there gives 0.
double scaledViscosity(double viscosity, bool up, double highestKappaSquared, double dt);

class StirSession {
public:
    /// Starts the prepared run at its initial state with no smoke, on `backend`; both must
    /// outlive the session.
    /// @throw modeflow::Error as Backend::makeSimulator does.
    StirSession(const Backend& backend, const RunInputs& run, StirSettings settings = {});

    /// The pointer, in scene coordinates (StirView::scenePoint).
    void press(const Vec3& point);
    void moveTo(const Vec3& point);
    void release();

    void reset();
    void toggleIntegrator();
    /// ν × 2, or ÷ 2; the first step up from 0 damps the basis's highest mode by 1/e in about
    /// 100 steps, and a step down from there gives 0.
    void scaleViscosity(bool up);
    void nextBasis();
    void togglePaddle();
    bool paddleMode() const { return mPaddleMode; }
    std::optional<PaddlePose> paddle() const;

    /// `steps` steps with the pointer's motion since the last call spread over them; `elapsed`:
    /// the window clock's seconds since the last call (the pointer's speed). The stats carry
    /// each stage's device time where the queue has timestamps and timing is on.
    FrameStats advance(int steps, double elapsed);
    /// Whether the following advance() calls time their steps (Simulation::setTiming).
    void setTiming(bool on) { mTiming = on; }

    const Simulator& simulation() const { return *mSimulations[mBasis]; }
    const SimulationSettings& settings() const { return simulation().settings(); }
    int modeCount() const { return mBases[mBasis].modes; }
    /// ½|v|², read from the device.
    double energy() const;
    /// One line: integrator, viscosity, basis, mouse mode.
    std::string status() const;

private:
    Simulator& current() { return *mSimulations[mBasis]; }
    /// The simulation of basis b, built the first time it is asked for.
    Simulator& simulationOf(std::size_t b);
    std::vector<ForceSplat> strokeSplats(double elapsed) const;
    MovingObstacle paddleObstacle(int steps) const;

    const Backend& mBackend;
    const RunInputs& mRun;
    SimulationSettings mSceneSettings;  ///< the run's, with the user's integrator and viscosity
    StirSettings mStir;
    double mBoxSize = 1.0;
    int mDim = 2;
    std::vector<ShapedBasis> mBases;
    /// Per shaped basis but the last (the run's own): its leading modes as a run of their own.
    std::vector<std::unique_ptr<RunInputs>> mShapedRuns;
    std::vector<std::unique_ptr<Simulator>> mSimulations;  ///< per basis, null until used
    std::size_t mBasis = 0;

    bool mPaddleMode = false;
    bool mDragging = false;
    bool mTiming = true;
    Vec3 mPointer{};     ///< now
    Vec3 mStrokeFrom{};  ///< at the last step
    Vec3 mPaddleAt{};
    double mStrokeTime = 0.0;  ///< window seconds since mStrokeFrom
};

}  // namespace modeflow::stir
