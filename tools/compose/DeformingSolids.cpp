#include "tools/compose/DeformingSolids.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>

#include "engine/core/Error.h"
#include "engine/core/FileKind.h"
#include "engine/core/MeshSequence.h"
#include "engine/core/NumberText.h"
#include "precompute/geometry/ObjMesh.h"
#include "tools/compose/MeshLattice.h"

namespace modeflow {
namespace {

/// More files than any run shows (a second at 24 files a second is 24).
constexpr double kMaxSequenceFiles = 100000.0;

double distance2(const Vec3& a, const Vec3& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

Vec3 samplePosition(const SolidLevelSet& set, int x, int y, int z) {
    return {set.origin[0] + x * set.spacing, set.origin[1] + y * set.spacing,
            set.origin[2] + z * set.spacing};
}

/// Calls f(sample index, x, y, z) for the samples inside the solid or within two samples of it:
/// those whose velocity a covered point can read.
template <typename F>
void forEachNearSample(const SolidLevelSet& set, F&& f) {
    std::size_t i = 0;
    for (int z = 0; z < set.samples[2]; ++z)
        for (int y = 0; y < set.samples[1]; ++y)
            for (int x = 0; x < set.samples[0]; ++x, ++i)
                if (set.depth[i] >= -2.0 * set.spacing) f(i, x, y, z);
}

void setVelocity(SolidLevelSet& set, std::size_t sample, const Vec3& v) {
    for (int a = 0; a < 3; ++a) set.velocity[3 * sample + std::size_t(a)] = float(v[a]);
    set.maxSpeed = std::max(set.maxSpeed, std::sqrt(distance2(v, {0.0, 0.0, 0.0})));
}

/// The vertices' own velocities (to − from) · rate, spread to the samples by inverse-distance
/// weights of the vertices in the bins around each (bins as wide as the longest edge, at least
/// three samples), farther rings of bins where those hold none.
void vertexVelocity(SolidLevelSet& set, const TriangleMesh& from, const TriangleMesh& to,
                    double rate) {
    double longest = 3.0 * set.spacing;
    for (const auto& t : from.triangles)
        for (int e = 0; e < 3; ++e)
            longest =
                std::max(longest, std::sqrt(distance2(from.vertices[std::size_t(t[e])],
                                                      from.vertices[std::size_t(t[(e + 1) % 3])])));
    const double width = longest;
    const auto binOf = [&](const Vec3& p) {
        std::array<std::int64_t, 3> b{};
        for (int a = 0; a < 3; ++a) b[a] = std::int64_t(std::floor(p[a] / width));
        return b;
    };
    const auto key = [](const std::array<std::int64_t, 3>& b) {
        return ((b[0] + (1 << 20)) << 42) | ((b[1] + (1 << 20)) << 21) | (b[2] + (1 << 20));
    };
    std::unordered_map<std::int64_t, std::vector<std::size_t>> bins;
    for (std::size_t v = 0; v < from.vertices.size(); ++v)
        bins[key(binOf(from.vertices[v]))].push_back(v);
    const double soft = 0.01 * set.spacing * set.spacing;
    forEachNearSample(set, [&](std::size_t sample, int x, int y, int z) {
        const Vec3 p = samplePosition(set, x, y, z);
        const auto centre = binOf(p);
        Vec3 sum{0.0, 0.0, 0.0};
        double weights = 0.0;
        for (int ring = 1; ring <= 8 && weights == 0.0; ++ring)
            for (std::int64_t dz = -ring; dz <= ring; ++dz)
                for (std::int64_t dy = -ring; dy <= ring; ++dy)
                    for (std::int64_t dx = -ring; dx <= ring; ++dx) {
                        // Each ring adds only its shell.
                        if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < ring - 1)
                            continue;
                        const auto found =
                            bins.find(key({centre[0] + dx, centre[1] + dy, centre[2] + dz}));
                        if (found == bins.end()) continue;
                        for (const std::size_t v : found->second) {
                            const double w = 1.0 / (distance2(p, from.vertices[v]) + soft);
                            for (int a = 0; a < 3; ++a)
                                sum[a] += w * (to.vertices[v][a] - from.vertices[v][a]) * rate;
                            weights += w;
                        }
                    }
        if (weights > 0.0)
            setVelocity(set, sample, {sum[0] / weights, sum[1] / weights, sum[2] / weights});
    });
}

/// The surface's motion from the level sets alone: −(d' − d) · rate · ∇d / |∇d|², normal to it.
void levelSetVelocity(SolidLevelSet& set, const SolidLevelSet& next, double rate) {
    const auto depth = [&](int x, int y, int z) {
        x = std::clamp(x, 0, set.samples[0] - 1);
        y = std::clamp(y, 0, set.samples[1] - 1);
        z = std::clamp(z, 0, set.samples[2] - 1);
        return double(set.depth[std::size_t(x) + std::size_t(set.samples[0]) *
                                                     (std::size_t(y) + std::size_t(set.samples[1]) *
                                                                           std::size_t(z))]);
    };
    forEachNearSample(set, [&](std::size_t sample, int x, int y, int z) {
        const Vec3 gradient{(depth(x + 1, y, z) - depth(x - 1, y, z)) / (2.0 * set.spacing),
                            (depth(x, y + 1, z) - depth(x, y - 1, z)) / (2.0 * set.spacing),
                            (depth(x, y, z + 1) - depth(x, y, z - 1)) / (2.0 * set.spacing)};
        const double length2 = distance2(gradient, {0.0, 0.0, 0.0});
        if (length2 < 1e-6) return;
        const double change = (double(next.depth[sample]) - double(set.depth[sample])) * rate;
        setVelocity(set, sample,
                    {-change * gradient[0] / length2, -change * gradient[1] / length2,
                     -change * gradient[2] / length2});
    });
}

}  // namespace

std::vector<std::shared_ptr<const SolidLevelSet>> deformingSolids(const SceneSpec& scene,
                                                                  std::size_t index,
                                                                  double spacing) {
    const ObstacleSpec& obstacle = scene.obstacles[index];
    const std::string entry =
        scene.sourceFile.string() + ": [[obstacle]] #" + std::to_string(index + 1);
    const double end = scene.output.frames * scene.output.stepsPerFrame * scene.simulation.dt;
    const double shown = std::floor(end * obstacle.sequenceRate) + 1.0;
    if (!(shown <= kMaxSequenceFiles))
        throw Error(entry + ": the run reaches t = " + numberText(end) + ", file " +
                    numberText(shown) + " of its sequence at sequence_rate " +
                    numberText(obstacle.sequenceRate) + "; at most " +
                    numberText(kMaxSequenceFiles) + " files");
    const int needed = int(shown);
    const int available = sequenceLength(obstacle.meshFile, needed + 1);
    if (available < needed) {
        const std::filesystem::path gap = sequenceFile(obstacle.meshFile, available + 1);
        const std::optional<std::string> why = whyNotARegularFile(gap);
        throw Error(entry + ": " + gap.string() + " " +
                    (why && *why != "does not exist" ? *why + ", not an OBJ file" : "is missing") +
                    ": the run reaches t = " + numberText(end) + ", which shows file " +
                    std::to_string(needed) + " of the sequence (sequence_rate " +
                    numberText(obstacle.sequenceRate) + ")");
    }
    std::vector<TriangleMesh> meshes;
    std::vector<std::filesystem::path> files;
    for (int k = 1; k <= available; ++k) {
        files.push_back(sequenceFile(obstacle.meshFile, k));
        try {
            meshes.push_back(readObjMesh(files.back()));
        } catch (const Error& e) {
            throw Error(entry + ": " + e.what());
        }
    }
    auto [lo, hi] = meshBounds(meshes.front());
    for (const TriangleMesh& mesh : meshes) {
        const auto [meshLo, meshHi] = meshBounds(mesh);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], meshLo[a]);
            hi[a] = std::max(hi[a], meshHi[a]);
        }
    }
    const std::string where = entry + " (" + obstacle.meshFile.string() + ")";
    const SolidLevelSet lattice =
        latticeOver(lo, hi, spacing / obstacle.scale, obstacle.scale, where);
    const double samples = double(lattice.samples[0]) * lattice.samples[1] * lattice.samples[2];
    if (samples * needed > kMaxLatticeSamples)
        throw Error(where + ": " + std::to_string(needed) + " files of " + numberText(samples) +
                    " samples each take more than " + numberText(kMaxLatticeSamples) +
                    " samples; lower sequence_rate or shorten the run");
    std::vector<SolidLevelSet> sets(meshes.size(), lattice);
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        try {
            sampleDepth(sets[k], meshes[k], files[k], 0.0);
        } catch (const Error& e) {
            throw Error(entry + ": " + e.what());
        }
    }
    std::vector<std::shared_ptr<const SolidLevelSet>> shapes;
    for (std::size_t k = 0; k < std::size_t(needed); ++k) {
        SolidLevelSet& set = sets[k];
        set.velocity.assign(3 * set.depth.size(), 0.0f);
        if (k + 1 < sets.size()) {
            if (meshes[k].vertices.size() == meshes[k + 1].vertices.size())
                vertexVelocity(set, meshes[k], meshes[k + 1], obstacle.sequenceRate);
            else
                levelSetVelocity(set, sets[k + 1], obstacle.sequenceRate);
        }
        shapes.push_back(std::make_shared<const SolidLevelSet>(std::move(set)));
    }
    return shapes;
}

}  // namespace modeflow
