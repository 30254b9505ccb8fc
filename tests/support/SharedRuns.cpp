#include "tests/support/SharedRuns.h"

#include "tests/support/RealBases.h"

namespace modeflow::testing {

RunInputs sharedRun(const SceneSpec& scene) {
    return prepareRun(scene, sharedBasis(scene));
}

}  // namespace modeflow::testing
