/// Fuzz target: the OBJ reader and its level-set conversion (loadMeshShape on a scratch file).

#include <cmath>

#include "precompute/geometry/MeshLevelSet.h"
#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {

bool objReader(std::string_view bytes) {
    const auto input = scratchFile("input.obj", bytes);
    return acceptedOrRefused([&] {
        // Coarse voxels: the conversion's cost grows with the surface area over the voxel area,
        // and the reader's checks, not OpenVDB's speed, are what is fuzzed.
        const auto shape = loadMeshShape(input, 0.25);
        for (const Vec3& p : {Vec3{0.0, 0.0, 0.0}, Vec3{0.3, -0.2, 0.1}, Vec3{5.0, 5.0, 5.0}})
            require(std::isfinite(shape->value(p)), "a mesh shape's value is not finite");
    });
}

}  // namespace modeflow::fuzz
