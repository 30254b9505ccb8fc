#include "engine/simulation/RuntimeMemory.h"

namespace modeflow {

RunMemory estimateRunMemory(std::int64_t smokeCells, std::int64_t velocityDofs, int modes,
                            bool device) {
    constexpr double kMiB = 1024.0 * 1024.0;
    const double k = modes;
    RunMemory memory;
    memory.basisBytes = 3.0 * (double(velocityDofs) * k * 8.0 + k * k * (k - 1.0) / 2.0 * 8.0);
    memory.smokeBytes = double(smokeCells) * (device ? 200.0 : 150.0);
    memory.peakBytes =
        1.15 * ((device ? 150.0 : 48.0) * kMiB + memory.basisBytes + memory.smokeBytes);
    return memory;
}

}  // namespace modeflow
