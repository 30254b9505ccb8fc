/// @file VdbFrame.cpp
/// The one translation unit with OpenVDB includes of the engine (VdbFrame.h says why).

#include "engine/output/VdbFrame.h"

#include <openvdb/io/Archive.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <mutex>
#include <system_error>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;
namespace vdb = openvdb;

const char* const kPeriodicMetadata = "modeflow_periodic";

void initializeOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { vdb::initialize(); });
}

std::string quoted(const fs::path& file) {
    return "'" + file.string() + "'";
}

std::size_t size(const CellValues& values) {
    return std::visit([](auto span) { return span.size(); }, values);
}

/// What writeVdbFrame checks before any work, so a bad frame fails with a message about the
/// frame rather than an OpenVDB one.
void validate(const VdbFrame& frame) {
    const MacGrid& smoke = frame.smokeGrid;
    const auto cells = static_cast<std::size_t>(smoke.cellCount());
    const auto count = [](std::size_t n) { return std::to_string(n); };
    if (frame.basisGrid.dim != smoke.dim)
        throw Error("the smoke grid is " + std::to_string(smoke.dim) + "D but the basis grid is " +
                    std::to_string(frame.basisGrid.dim) + "D");
    if (frame.basisGrid.periodic != smoke.periodic)
        throw Error("the smoke grid and the basis grid differ in their periodic axes");
    if (size(frame.density) != cells)
        throw Error("density has " + count(size(frame.density)) + " values for " + count(cells) +
                    " smoke cells");
    for (const auto& [values, name] :
         {std::pair{&frame.temperature, "temperature"}, std::pair{&frame.fuel, "fuel"},
          std::pair{&frame.flame, "flame"}}) {
        const std::size_t n = size(*values);
        if (n != 0 && n != cells)
            throw Error(std::string(name) + " has " + count(n) + " values for " + count(cells) +
                        " smoke cells");
    }
    if (!frame.fluidMask.empty() && frame.fluidMask.size() != cells)
        throw Error("the fluid mask has " + count(frame.fluidMask.size()) + " entries for " +
                    count(cells) + " smoke cells");
    const auto checkFaceField = [&](std::span<const double> field, const std::string& name) {
        requireFaceField(frame.basisGrid, field.size(), name.c_str());
        for (std::size_t f = 0; f < field.size(); ++f)
            if (!std::isfinite(field[f]))
                throw Error(name + " is not finite at face " + count(f) +
                            " (the simulation diverged)");
    };
    checkFaceField(frame.faceVelocity, "the face velocity");
    if (!frame.faceMagnetic.empty()) checkFaceField(frame.faceMagnetic, "the face magnetic field");
    const double threshold = frame.options.activityThreshold;
    if (!(threshold >= 0.0) || !std::isfinite(threshold))
        throw Error("the activity threshold must be a finite number ≥ 0, got " +
                    std::to_string(threshold));
}

/// Voxel (i, j, k) ↔ smoke cell (i, j, k), the voxel centre at the cell centre. OpenVDB puts a
/// voxel's value at its integer index coordinates, so the translation is cell (0, 0, 0)'s centre,
/// not the box corner. Equal spacings give a uniform-scale map, which some tools special-case.
vdb::math::Transform::Ptr smokeTransform(const MacGrid& smoke) {
    vdb::Vec3d scale, translation;
    for (int a = 0; a < 3; ++a) {
        scale[a] = smoke.spacing[a];
        translation[a] = smoke.cellCentre(a, 0);
    }
    if (smoke.dim == 2) {  // one layer of voxels centred on z = 0, as deep as the thinner side
        scale[2] = std::min(smoke.spacing[0], smoke.spacing[1]);
        translation[2] = 0.0;
    }
    vdb::math::MapBase::Ptr map;
    if (scale[0] == scale[1] && scale[1] == scale[2])
        map = std::make_shared<vdb::math::UniformScaleTranslateMap>(scale[0], translation);
    else
        map = std::make_shared<vdb::math::ScaleTranslateMap>(scale, translation);
    return std::make_shared<vdb::math::Transform>(map);
}

void addFrameMetadata(vdb::MetaMap& meta, const VdbFrame& frame) {
    meta.insertMeta("frame", vdb::Int32Metadata(frame.frame));
    meta.insertMeta("time", vdb::DoubleMetadata(frame.time));
    meta.insertMeta("scene_hash", vdb::StringMetadata(frame.sceneHash));
    meta.insertMeta("modeflow_version", vdb::StringMetadata(frame.modeflowVersion));
    meta.insertMeta(vdb::GridBase::META_GRID_CREATOR, vdb::StringMetadata("modeflow"));
    const MacGrid& grid = frame.smokeGrid;
    if (grid.periodicBits() != 0)
        meta.insertMeta(
            kPeriodicMetadata,
            vdb::Vec3IMetadata(vdb::Vec3i(grid.periodic[0], grid.periodic[1], grid.periodic[2])));
}

/// The `modeflow_periodic` entry of `meta` as flags; empty when absent.
std::optional<std::array<bool, 3>> periodicFlags(const vdb::MetaMap& meta) {
    const auto flags = meta.getMetadata<vdb::Vec3IMetadata>(kPeriodicMetadata);
    if (!flags) return std::nullopt;
    const vdb::Vec3i& v = flags->value();
    return std::array<bool, 3>{v[0] != 0, v[1] != 0, v[2] != 0};
}

/// Sparse grid from a dense array in cellIndex order (x fastest: OpenVDB's LayoutXYZ). Entries
/// that are exactly 0 stay inactive background; callers zero whatever must be inactive.
template <typename GridT>
typename GridT::Ptr sparseGrid(const MacGrid& smoke, std::vector<typename GridT::ValueType>& dense,
                               const char* name, const VdbFrame& frame) {
    using ValueT = typename GridT::ValueType;
    const vdb::CoordBBox box(vdb::Coord(0, 0, 0), vdb::Coord(smoke.cells[0] - 1, smoke.cells[1] - 1,
                                                             smoke.cells[2] - 1));
    vdb::tools::Dense<ValueT, vdb::tools::LayoutXYZ> view(box, dense.data());
    auto grid = GridT::create(vdb::zeroVal<ValueT>());
    vdb::tools::copyFromDense(view, *grid, vdb::zeroVal<ValueT>());
    // copyFromDense turns uniform 8³ blocks into tiles; leaves only are what every importer
    // handles (some walk leaf nodes alone), for a few KB per uniform block.
    grid->tree().voxelizeActiveTiles();
    grid->setName(name);
    grid->setTransform(smokeTransform(smoke));
    grid->setSaveFloatAsHalf(frame.options.halfFloat);
    addFrameMetadata(*grid, frame);
    return grid;
}

bool isFluid(const VdbFrame& frame, std::size_t cell) {
    return frame.fluidMask.empty() || frame.fluidMask[cell] != 0;
}

vdb::FloatGrid::Ptr scalarGrid(const VdbFrame& frame, const CellValues& values, const char* name) {
    std::vector<float> dense(size(values));
    const double threshold = frame.options.activityThreshold;
    std::visit(
        [&](auto span) {
            for (std::size_t c = 0; c < span.size(); ++c) {
                const double v = span[c];
                if (!std::isfinite(v))
                    throw Error(std::string(name) + " is not finite in smoke cell " +
                                std::to_string(c) + " (the simulation diverged)");
                dense[c] = isFluid(frame, c) && std::abs(v) >= threshold ? float(v) : 0.0f;
            }
        },
        values);
    auto grid = sparseGrid<vdb::FloatGrid>(frame.smokeGrid, dense, name, frame);
    grid->setGridClass(vdb::GRID_FOG_VOLUME);
    return grid;
}

/// A MAC face field (the velocity, or the magnetic field) sampled at every smoke cell centre, so
/// it shares the lattice of the scalars; one z-y row of cells per task.
vdb::Vec3SGrid::Ptr vectorGrid(const VdbFrame& frame, std::span<const double> faceField,
                               const char* name) {
    const MacGrid& smoke = frame.smokeGrid;
    std::vector<vdb::Vec3s> dense(static_cast<std::size_t>(smoke.cellCount()));
    const double threshold = frame.options.activityThreshold;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, smoke.cells[1] * smoke.cells[2]), [&](const auto& rows) {
            for (int row = rows.begin(); row < rows.end(); ++row) {
                const int j = row % smoke.cells[1], k = row / smoke.cells[1];
                for (int i = 0; i < smoke.cells[0]; ++i) {
                    const auto c = static_cast<std::size_t>(smoke.cellIndex(i, j, k));
                    if (!isFluid(frame, c)) continue;
                    const Vec3 world{smoke.cellCentre(0, i), smoke.cellCentre(1, j),
                                     smoke.cellCentre(2, k)};
                    const Vec3 v = sampleVelocity(frame.basisGrid, faceField, world);
                    if (std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) >= threshold)
                        dense[c] = vdb::Vec3s(float(v[0]), float(v[1]), float(v[2]));
                }
            }
        });
    auto grid = sparseGrid<vdb::Vec3SGrid>(smoke, dense, name, frame);
    // Like a velocity: transformed by the map's linear part, translation ignored; the values are
    // in world units (Houdini's Transform VDB and Blender's motion blur read both settings).
    grid->setVectorType(vdb::VEC_CONTRAVARIANT_RELATIVE);
    grid->setIsInWorldSpace(true);
    return grid;
}

/// io::File::write opens its own stream and never looks at it after writing, so a full disk
/// would leave a truncated frame unnoticed. This writes the same seekable archive (grid offsets
/// included, as importers expect) into a stream we check.
class CheckedArchive : public vdb::io::Archive {
public:
    void writeTo(std::ofstream& os, const vdb::GridCPtrVec& grids, const vdb::MetaMap& meta) const {
        Archive::write(os, grids, /*seekable=*/true, meta);
    }
};

/// The C library's word for the last failed call; streams keep no error of their own.
std::string systemCause() {
    return errno != 0 ? std::strerror(errno) : "input/output error";
}

void writeArchive(const fs::path& temporary, const vdb::GridCPtrVec& grids,
                  const vdb::MetaMap& meta) {
    errno = 0;
    std::ofstream os(temporary, std::ios::out | std::ios::binary | std::ios::trunc);
    if (!os)
        throw Error("cannot write VDB frame: cannot create " + quoted(temporary) + ": " +
                    systemCause());
    CheckedArchive archive;
    // Blosc is fast and what both applications ship with; ZIP is far slower (and OpenVDB skips it
    // for fog volumes anyway).
    if (vdb::io::Archive::hasBloscCompression())
        archive.setCompression(vdb::io::COMPRESS_BLOSC | vdb::io::COMPRESS_ACTIVE_MASK);
    archive.writeTo(os, grids, meta);
    os.flush();
    const bool written = bool(os);
    os.close();
    if (!written || os.fail())
        throw Error("cannot write VDB frame: writing " + quoted(temporary) +
                    " failed: " + systemCause());
}

}  // namespace

void writeVdbFrame(const fs::path& file, const VdbFrame& frame) {
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw Error("cannot write VDB frame " + quoted(file) + ": folder " + quoted(folder) +
                    " does not exist");
    vdb::GridCPtrVec grids;
    vdb::MetaMap meta;
    try {
        validate(frame);
        initializeOpenVdb();
        grids.push_back(scalarGrid(frame, frame.density, "density"));
        for (const auto& [values, name] :
             {std::pair{&frame.temperature, "temperature"}, std::pair{&frame.fuel, "fuel"},
              std::pair{&frame.flame, "flame"}})
            if (size(*values) != 0) grids.push_back(scalarGrid(frame, *values, name));
        grids.push_back(vectorGrid(frame, frame.faceVelocity, "vel"));
        if (!frame.faceMagnetic.empty())
            grids.push_back(vectorGrid(frame, frame.faceMagnetic, "magnetic"));
        addFrameMetadata(meta, frame);
    } catch (const std::exception& e) {
        throw Error("cannot write VDB frame " + quoted(file) + ": " + e.what());
    }
    writeFileAtomically(file, "VDB frame", [&](const fs::path& temporary) {
        try {
            writeArchive(temporary, grids, meta);
        } catch (const Error&) {
            throw;
        } catch (const std::exception& e) {  // OpenVDB's own exceptions
            throw Error("cannot write VDB frame " + quoted(file) + ": " + e.what());
        }
    });
}

std::string frameFileName(std::string_view sceneName, int frame) {
    if (sceneName.empty()) throw Error("a VDB frame file needs a scene name");
    if (frame < 0) throw Error("frame numbers start at 0, got " + std::to_string(frame));
    char digits[16];
    std::snprintf(digits, sizeof digits, "%04d", frame);
    return std::string(sceneName) + "_" + digits + ".vdb";
}

Vec3 VdbGridInfo::indexToWorld(double i, double j, double k) const {
    const auto& m = indexToWorldMatrix;
    Vec3 world;
    for (int c = 0; c < 3; ++c) world[c] = i * m[c] + j * m[4 + c] + k * m[8 + c] + m[12 + c];
    return world;
}

const VdbGridInfo* VdbFrameInfo::grid(std::string_view name) const {
    for (const VdbGridInfo& g : grids)
        if (g.name == name) return &g;
    return nullptr;
}

namespace {

/// An open file, or an Error naming it: OpenVDB's own messages do not say which file.
std::unique_ptr<vdb::io::File> openForReading(const fs::path& file) {
    initializeOpenVdb();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw Error("cannot read VDB frame " + quoted(file) + ": no such file");
    auto vdbFile = std::make_unique<vdb::io::File>(file.string());
    try {
        // No delayed loading: read everything now, so a truncated file fails here and the file
        // is not kept mapped behind the caller's back.
        vdbFile->open(/*delayLoad=*/false);
    } catch (const std::exception& e) {
        throw Error("cannot read VDB frame " + quoted(file) + ": " + e.what());
    }
    return vdbFile;
}

template <typename T>
std::optional<T> metaValue(const vdb::MetaMap& meta, const std::string& name) {
    if (const auto typed = meta.getMetadata<vdb::TypedMetadata<T>>(name)) return typed->value();
    return std::nullopt;
}

VdbGridInfo gridInfo(const vdb::GridBase& grid) {
    VdbGridInfo info;
    info.name = grid.getName();
    info.gridClass = vdb::GridBase::gridClassToString(grid.getGridClass());
    info.valueType = grid.valueType();
    info.vectorType = vdb::GridBase::vecTypeToString(grid.getVectorType());
    info.savedAsHalf = grid.saveFloatAsHalf();
    info.valuesInWorldSpace = grid.isInWorldSpace();
    info.activeVoxels = static_cast<std::int64_t>(grid.activeVoxelCount());
    info.periodic = periodicFlags(grid);
    const vdb::Vec3d voxel = grid.voxelSize();
    info.voxelSize = {voxel[0], voxel[1], voxel[2]};
    const vdb::Mat4d m = grid.transform().baseMap()->getAffineMap()->getMat4();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) info.indexToWorldMatrix[4 * r + c] = m(r, c);
    return info;
}

template <typename GridT>
void sampleGrid(const GridT& grid, std::span<const Vec3> points, std::vector<VdbSample>& out) {
    const auto accessor = grid.getConstAccessor();
    for (const Vec3& p : points) {
        const vdb::Coord ijk =
            grid.transform().worldToIndexCellCentered(vdb::Vec3d(p[0], p[1], p[2]));
        VdbSample sample;
        sample.active = accessor.isValueOn(ijk);
        const auto value = accessor.getValue(ijk);
        if constexpr (vdb::VecTraits<typename GridT::ValueType>::IsVec)
            sample.value = {value[0], value[1], value[2]};
        else
            sample.value[0] = value;
        out.push_back(sample);
    }
}

}  // namespace

VdbFrameInfo readVdbFrameInfo(const fs::path& file) {
    const auto vdbFile = openForReading(file);
    VdbFrameInfo info;
    try {
        const vdb::MetaMap::Ptr meta = vdbFile->getMetadata();
        info.frame = metaValue<std::int32_t>(*meta, "frame");
        info.time = metaValue<double>(*meta, "time");
        info.sceneHash = metaValue<std::string>(*meta, "scene_hash").value_or("");
        info.modeflowVersion = metaValue<std::string>(*meta, "modeflow_version").value_or("");
        info.creator = metaValue<std::string>(*meta, vdb::GridBase::META_GRID_CREATOR).value_or("");
        info.periodic = periodicFlags(*meta);
        const vdb::GridPtrVecPtr grids = vdbFile->getGrids();  // kept: the loop borrows its vector
        for (const vdb::GridBase::Ptr& grid : *grids) info.grids.push_back(gridInfo(*grid));
    } catch (const std::exception& e) {
        throw Error("cannot read VDB frame " + quoted(file) + ": " + e.what());
    }
    return info;
}

std::vector<VdbSample> sampleVdbGrid(const fs::path& file, std::string_view gridName,
                                     std::span<const Vec3> worldPoints) {
    const auto vdbFile = openForReading(file);
    const std::string name(gridName);
    if (!vdbFile->hasGrid(name))
        throw Error("VDB frame " + quoted(file) + " has no grid '" + name + "'");
    vdb::GridBase::Ptr grid;
    try {
        grid = vdbFile->readGrid(name);
    } catch (const std::exception& e) {
        throw Error("cannot read grid '" + name + "' of VDB frame " + quoted(file) + ": " +
                    e.what());
    }
    std::vector<VdbSample> samples;
    samples.reserve(worldPoints.size());
    if (const auto g = vdb::gridConstPtrCast<vdb::FloatGrid>(grid))
        sampleGrid(*g, worldPoints, samples);
    else if (const auto g = vdb::gridConstPtrCast<vdb::DoubleGrid>(grid))
        sampleGrid(*g, worldPoints, samples);
    else if (const auto g = vdb::gridConstPtrCast<vdb::Vec3SGrid>(grid))
        sampleGrid(*g, worldPoints, samples);
    else if (const auto g = vdb::gridConstPtrCast<vdb::Vec3DGrid>(grid))
        sampleGrid(*g, worldPoints, samples);
    else
        throw Error("grid '" + name + "' of VDB frame " + quoted(file) + " holds " +
                    grid->valueType() + " values, which cannot be sampled here");
    return samples;
}

}  // namespace modeflow
