#include "tools/compose/RunIdentity.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

#include "engine/core/BinaryCodec.h"
#include "engine/core/MeshSequence.h"
#include "precompute/Precompute.h"

namespace modeflow {
namespace {

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string hex(std::uint64_t value) {
    std::ostringstream s;
    s << std::hex << std::setw(16) << std::setfill('0') << value;
    return s.str();
}

}  // namespace

RunIdentity runIdentity(const SceneSpec& scene, BackendKind backend) {
    return runIdentity(scene, backend, fileBytes(scene.sourceFile));
}

RunIdentity runIdentity(const SceneSpec& scene, BackendKind backend, std::string_view sceneText) {
    RunIdentity id;
    id.sceneHash = hex(fnv1a64(sceneText));
    // Mesh obstacles' and sources' files are part of the run: changing one changes the frames.
    std::string meshes;
    const auto addMesh = [&](const std::filesystem::path& file) {
        meshes.append(1, '|').append(hex(fnv1a64(fileBytes(file))));
    };
    for (const ObstacleSpec& obstacle : scene.obstacles) {
        if (obstacle.shape != ObstacleShape::Mesh) continue;
        if (obstacle.sequenceRate == 0.0) {
            addMesh(obstacle.meshFile);
            continue;
        }
        // A deforming one's files as far as the folder holds them (the run checks it has those
        // it shows).
        const int count = sequenceLength(obstacle.meshFile, 100000);
        for (int k = 1; k <= count; ++k) addMesh(sequenceFile(obstacle.meshFile, k));
    }
    for (const SourceSpec& source : scene.sources)
        if (source.shape.kind == ShapeKind::Mesh) addMesh(source.shape.meshFile);
    id.runHash = fnv1a64(id.sceneHash + "|" + basisKey(scene) + "|" +
                         std::string(capabilitiesOf(backend).option) + meshes);
    return id;
}

}  // namespace modeflow
