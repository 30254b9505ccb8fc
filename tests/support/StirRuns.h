#pragma once
/// @file StirRuns.h
/// The scenes `modeflow stir`'s loop tests run (in a window under Xvfb: StirWindowSlowTest; on a
/// NullScreen: StirLoopTest) and what they measure in the results.

#include <string>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "engine/preview/Image.h"
#include "engine/run/RunInputs.h"

namespace modeflow::testing {

/// A box with a source at the bottom; `dim` 2: 40² cells and the shaped basis "1-10,21-30";
/// 3: 16³ cells and 12 modes.
SceneSpec stirScene(int dim);

/// The scene's run on its shared basis (sharedRun), its initial velocity zero; once per process.
const RunInputs& preparedStirRun(int dim);

/// The density's centre of mass, in scene coordinates.
Vec3 smokeCentroid(int dim, const std::vector<double>& density);

/// The horizontal centre of a picture's bright pixels (the smoke: the background, walls and
/// margins are dark); -1 when there are none.
double brightCentreX(const preview::Image& picture);

/// A left drag along y = 0.75 of the window (through the source) from x0 to x1.
std::string drag(double x0, double x1, const std::string& before = "");

}  // namespace modeflow::testing
