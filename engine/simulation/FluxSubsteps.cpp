#include "engine/simulation/FluxSubsteps.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"

namespace modeflow {

int fluxSubsteps(double worst) {
    if (!(2.0 * worst <= maxFluxSubsteps))
        throw Error("conservative smoke advection: the air crosses " + std::to_string(worst) +
                    " smoke cells in a step, beyond the " + std::to_string(maxFluxSubsteps / 2) +
                    " its substeps allow; lower [simulation].dt or use another [smoke].advection");
    return std::max(1, int(std::ceil(2.0 * worst)));
}

}  // namespace modeflow
