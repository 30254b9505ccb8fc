#include "engine/device/SplatRecords.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow::device {

std::vector<shaders::ForceSplatRecord> splatRecords(std::span<const ForceSplat> splats,
                                                    std::size_t maxSplats, const char* kernel) {
    if (splats.size() > maxSplats)
        throw Error(std::string(kernel) + ": " + std::to_string(splats.size()) +
                    " splats, room for " + std::to_string(maxSplats));
    std::vector<shaders::ForceSplatRecord> records(splats.size());
    for (std::size_t k = 0; k < splats.size(); ++k) {
        if (!(splats[k].radius > 0.0))
            throw Error(std::string(kernel) + ": a splat radius must be positive, got " +
                        std::to_string(splats[k].radius));
        for (int a = 0; a < 3; ++a) {
            records[k].centre[a] = float(splats[k].centre[a]);
            records[k].force[a] = float(splats[k].force[a]);
        }
        records[k].radius = float(splats[k].radius);
    }
    return records;
}

}  // namespace modeflow::device
