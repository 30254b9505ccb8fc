#include "engine/simulation/RunMemory.h"

namespace modeflow {

double denseCoefficientBytes(int modes) {
    const double k = modes;
    return k * k * (k - 1.0) / 2.0 * 8.0;
}

RunMemory estimateRunMemory(std::int64_t smokeCells, double columnBytes, double coefficientBytes,
                            std::int64_t particles, bool device) {
    constexpr double kMiB = 1024.0 * 1024.0;
    RunMemory memory;
    memory.basisBytes = 3.0 * (columnBytes + coefficientBytes);
    memory.smokeBytes = double(smokeCells) * (device ? 200.0 : 150.0);
    memory.particleBytes = 256.0 * double(particles);
    memory.peakBytes = 1.15 * ((device ? 150.0 : 48.0) * kMiB + memory.basisBytes +
                               memory.smokeBytes + memory.particleBytes);
    return memory;
}

}  // namespace modeflow
