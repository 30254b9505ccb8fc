/// @file MeshLevelSet.cpp
/// The one translation unit with OpenVDB includes.

#include "precompute/geometry/MeshLevelSet.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include "engine/core/Error.h"
#include "precompute/geometry/ClosedSurfaceCheck.h"
#include "precompute/geometry/ObjMesh.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

/// Beyond this many band voxels the conversion would take gigabytes: the voxel size is a typo
/// or far too fine for the mesh.
constexpr double kMaxBandVoxels = 4.0e8;
/// Beyond this many voxels across, the conversion's time and memory grow with the extent even
/// when the band is small (a long sliver ran for minutes and took gigabytes: precompute/README.md
/// "How the precompute works"). The widest grid is 4096 cells of two voxels.
constexpr double kMaxExtentVoxels = 131072;

/// A count for messages: two significant digits, never an overflowed integer cast.
std::string roughCount(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2g", x);
    return buffer;
}

/// The shortest text that reads back as `x`.
template <typename T>
std::string shortest(T x) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return ec == std::errc{} ? std::string(buffer, end) : std::to_string(x);
}

void initializeOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

struct RawMesh {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
};

/// The mesh's triangles (read from `file` by ObjMesh.h) without those with a repeated vertex, which
/// have no area. meshToLevelSet silently produces garbage signs for a surface with holes, so the
/// surface must be closed (ClosedSurfaceCheck.h).
RawMesh rawMesh(const TriangleMesh& obj, const fs::path& file) {
    requireClosedSurface(obj, file);
    RawMesh mesh;
    mesh.points.reserve(obj.vertices.size());
    for (const Vec3& p : obj.vertices)
        mesh.points.emplace_back(float(p[0]), float(p[1]), float(p[2]));
    for (const auto& [a, b, c] : obj.triangles) {
        if (a == b || b == c || c == a) continue;
        mesh.triangles.emplace_back(std::uint32_t(a), std::uint32_t(b), std::uint32_t(c));
    }
    if (mesh.triangles.empty())
        throw Error("mesh file " + file.string() +
                    " has only degenerate faces (repeated vertices)");
    return mesh;
}

/// Refuses a mesh more than kMaxExtentVoxels across on some axis (vertices of its triangles).
void requireSaneExtent(const RawMesh& mesh, double voxelSize, const std::string& name) {
    openvdb::Vec3s lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            lo = openvdb::math::minComponent(lo, mesh.points[t[k]]);
            hi = openvdb::math::maxComponent(hi, mesh.points[t[k]]);
        }
    }
    for (int a = 0; a < 3; ++a) {
        const double voxels = (double(hi[a]) - double(lo[a])) / voxelSize;
        if (voxels > kMaxExtentVoxels)
            throw Error("mesh file " + name + " spans " + roughCount(voxels) + " voxels (of " +
                        shortest(voxelSize) + ") along " + "xyz"[a] + ", from " + shortest(lo[a]) +
                        " to " + shortest(hi[a]) + "; at most " + shortest(kMaxExtentVoxels) +
                        ": the mesh is far larger than the grid (are its units right?)");
    }
}

double surfaceArea(const RawMesh& mesh) {
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        const openvdb::Vec3d a(mesh.points[t[0]]), b(mesh.points[t[1]]), c(mesh.points[t[2]]);
        area += 0.5 * (b - a).cross(c - a).length();
    }
    return area;
}

class MeshLevelSet final : public ImplicitShape {
public:
    explicit MeshLevelSet(openvdb::FloatGrid::ConstPtr grid) : mGrid(std::move(grid)) {}

    double value(const Vec3& p) const override {
        // A fresh *unsafe* accessor per call: the safe kind registers itself with the tree under
        // a lock, and a shared one would race on its node cache. The tree is never modified
        // after construction, so concurrent reads through private accessors are safe.
        auto accessor = mGrid->getConstUnsafeAccessor();
        const openvdb::Vec3d index =
            mGrid->transform().worldToIndex(openvdb::Vec3d(p[0], p[1], p[2]));
        // OpenVDB's level sets are negative inside; χ is positive inside.
        return -static_cast<double>(openvdb::tools::BoxSampler::sample(accessor, index));
    }

private:
    openvdb::FloatGrid::ConstPtr mGrid;
};

}  // namespace

std::unique_ptr<ImplicitShape> loadMeshShape(const fs::path& objFile, double voxelSize,
                                             double halfWidthVoxels) {
    return loadMeshShape(readObjMesh(objFile), objFile, voxelSize, halfWidthVoxels);
}

std::unique_ptr<ImplicitShape> loadMeshShape(const TriangleMesh& obj, const fs::path& objFile,
                                             double voxelSize, double halfWidthVoxels) {
    const std::string name = objFile.string();
    if (!(voxelSize > 0.0) || !std::isfinite(voxelSize))
        throw Error("mesh file " + name + ": the level-set voxel size must be a positive number");
    if (!(halfWidthVoxels >= 1.0) || !std::isfinite(halfWidthVoxels))
        throw Error("mesh file " + name + ": the level-set half width must be at least 1 voxel");

    const RawMesh mesh = rawMesh(obj, objFile);

    requireSaneExtent(mesh, voxelSize, name);
    const double bandVoxels = surfaceArea(mesh) / (voxelSize * voxelSize) * 2.0 * halfWidthVoxels;
    if (bandVoxels > kMaxBandVoxels)
        throw Error("mesh file " + name + ": a level set with voxel size " +
                    std::to_string(voxelSize) + " would need about " + roughCount(bandVoxels) +
                    " voxels (at most " + roughCount(kMaxBandVoxels) + "); use a coarser grid");

    initializeOpenVdb();
    openvdb::FloatGrid::Ptr grid;
    try {
        const auto transform = openvdb::math::Transform::createLinearTransform(voxelSize);
        grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
            *transform, mesh.points, mesh.triangles, static_cast<float>(halfWidthVoxels));
    } catch (const openvdb::Exception& e) {
        throw Error("mesh file " + name + ": level-set conversion failed: " + e.what());
    }
    // A doubled sheet passes the edge test yet bounds nothing; so does a mesh much thinner than
    // a voxel. Either way no voxel lies clearly inside (negative in OpenVDB's convention): voxels
    // on a sheet's plane get float noise of either sign, hence the margin.
    bool enclosesVolume = false;
    if (grid) {
        const float inside = -0.1f * static_cast<float>(voxelSize);
        for (auto it = grid->cbeginValueOn(); it && !enclosesVolume; ++it)
            enclosesVolume = *it < inside;
    }
    if (!enclosesVolume)
        throw Error("mesh file " + name + " encloses no volume at voxel size " +
                    std::to_string(voxelSize) +
                    " (a flat or doubled surface, or one thinner than a voxel)");
    return std::make_unique<MeshLevelSet>(std::move(grid));
}

}  // namespace modeflow
