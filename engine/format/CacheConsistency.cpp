#include "engine/format/CacheConsistency.h"

#include <cmath>
#include <cstdint>
#include <functional>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/core/PackedLayout.h"

namespace modeflow {
namespace {

bool known(WallKind wall) {
    switch (wall) {
        case WallKind::FreeSlip:
        case WallKind::NoSlip:
            return true;
    }
    return false;
}
bool known(BoundaryTreatment boundary) {
    switch (boundary) {
        case BoundaryTreatment::CutCell:
        case BoundaryTreatment::Staircase:
            return true;
    }
    return false;
}
bool known(ScalarBoundary boundary) {
    switch (boundary) {
        case ScalarBoundary::Neumann:
        case ScalarBoundary::Dirichlet:
            return true;
    }
    return false;
}
bool known(BasisCache::Coefficients::Storage storage) {
    switch (storage) {
        case BasisCache::Coefficients::Storage::Dense:
        case BasisCache::Coefficients::Storage::Sparse:
        case BasisCache::Coefficients::Storage::None:
            return true;
    }
    return false;
}

bool known(BasisSource source) {
    switch (source) {
        case BasisSource::Eigensolve:
        case BasisSource::ClosedForm:
            return true;
    }
    return false;
}

/// Wave numbers 0..n_a (a Dirichlet scalar's reach n_a) on the grid's axes, 0 beyond; phases 0 or
/// 1; finite amplitudes.
bool separableWithinGrid(const std::vector<SeparableMode>& modes, const GridSpec& grid) {
    for (const SeparableMode& m : modes)
        for (int a = 0; a < 3; ++a) {
            const int limit = a < grid.dim ? grid.resolution[a] : 0;
            if (m.wave[a] < 0 || m.wave[a] > limit || m.shift[a] > 1 ||
                !std::isfinite(m.amplitude[a]))
                return false;
        }
    return true;
}

/// A sparse matrix whose row starts rise from 0 to its entry count and whose columns lie below
/// `columns`.
bool wellFormed(const SparseRows& m, std::int64_t columns) {
    if (m.start.empty() || m.start.front() != 0 ||
        m.start.back() != std::int64_t(m.column.size()) || m.column.size() != m.value.size())
        return false;
    for (std::size_t r = 1; r < m.start.size(); ++r)
        if (m.start[r] < m.start[r - 1]) return false;
    for (const std::int32_t col : m.column)
        if (col < 0 || col >= columns) return false;
    return true;
}

template <typename Index>
bool allBelow(const std::vector<Index>& indices, std::int64_t end) {
    for (const Index i : indices)
        if (i < 0 || std::int64_t(i) >= end) return false;
    return true;
}

/// The grid's cell count, or -1 when its resolution is not 2D or 3D with at most `cellLimit` cells.
std::int64_t cellCount(const GridSpec& grid, std::size_t cellLimit) {
    if (grid.dim != 2 && grid.dim != 3) return -1;
    if (grid.dim == 2 && grid.resolution[2] != 1) return -1;
    std::int64_t cells = 1;
    for (const int n : grid.resolution) {
        if (n < 1 || std::uint64_t(n) > cellLimit) return -1;
        cells *= n;
        if (std::uint64_t(cells) > cellLimit) return -1;
    }
    return cells;
}

using Require = std::function<void(bool holds, const char* what)>;

/// The eigenvalues, mode numbers and coefficients of `n` velocity modes (either kind of basis).
void requireConsistentSpectrum(const BasisCache& c, Eigen::Index n, const Require& require) {
    const auto& v = c.velocity;
    require(v.eigenvalues.size() == n && Eigen::Index(v.modeNumbers.size()) == n &&
                v.harmonic >= 0 && v.harmonic <= n,
            "its velocity eigenvalues, mode numbers or harmonic count disagree with its modes");
    const auto& co = c.coefficients;
    require(known(co.storage), "its coefficient storage is out of range");
    if (co.storage == BasisCache::Coefficients::Storage::None) {
        require(
            co.packed.empty() && co.value.empty() && co.k.empty() && co.i.empty() && co.j.empty(),
            "it holds coefficients though its storage says none");
    } else if (co.storage == BasisCache::Coefficients::Storage::Dense) {
        require(co.packed.size() == packedSize(std::size_t(n)) && co.value.empty() && co.k.empty(),
                "its dense coefficients do not hold N²(N−1)/2 values for its N velocity modes");
    } else {
        bool ordered = co.k.size() == co.value.size() && co.i.size() == co.value.size() &&
                       co.j.size() == co.value.size() && co.packed.empty();
        for (std::size_t e = 0; ordered && e < co.value.size(); ++e)
            ordered =
                co.k[e] >= 0 && co.k[e] < co.j[e] && co.j[e] < n && co.i[e] >= 0 && co.i[e] < n;
        require(ordered, "its sparse coefficients are not entries k < j of its velocity modes");
    }
}

/// A surface basis (BasisCache::Surface): edges carry the velocity, triangles the divergence,
/// vertices the scalar; every index lies on the mesh and every matrix has their sizes.
void requireConsistentSurface(const BasisCache& c, const Require& require) {
    const auto& s = c.surface;
    const auto vertices = std::int64_t(s.mesh.vertices.size());
    const auto edges = Eigen::Index(s.edges.size()),
               triangles = Eigen::Index(s.mesh.triangles.size());
    bool onMesh = true;
    for (const auto& t : s.mesh.triangles)
        for (const int v : t) onMesh = onMesh && v >= 0 && v < vertices;
    for (const auto& e : s.edges)
        for (const int v : e) onMesh = onMesh && v >= 0 && v < vertices;
    require(onMesh, "its surface's triangles or edges name vertices it does not have");
    const auto& v = c.velocity;
    const auto& sc = c.scalar;
    require(v.source == BasisSource::Eigensolve && sc.source == BasisSource::Eigensolve &&
                v.separable.empty() && sc.separable.empty(),
            "its surface basis holds closed-form modes");
    require(Eigen::Index(c.faces.size()) == edges && c.faceStar.size() == edges &&
                v.modes.rows() == edges && allBelow(c.faces, edges),
            "its velocity degrees of freedom disagree with its surface's edges");
    require(Eigen::Index(c.cells.size()) == triangles && c.cellStar.size() == triangles &&
                allBelow(c.cells, triangles),
            "its divergence degrees of freedom disagree with its surface's triangles");
    require(Eigen::Index(sc.cells.size()) == vertices && sc.cellStar.size() == vertices &&
                sc.modes.rows() == vertices && allBelow(sc.cells, vertices) &&
                sc.eigenvalues.size() == sc.modes.cols() && sc.omittedConstants >= 0,
            "its scalar modes disagree with its surface's vertices or their eigenvalues");
    const Eigen::Index n = v.modes.cols();
    require(s.advection.rows() == Eigen::Index(pairCount(std::size_t(sc.modes.cols()))) &&
                s.advection.cols() == n && s.vertexVelocity.rows() == 3 * vertices &&
                s.vertexVelocity.cols() == n,
            "its surface advection or vertex velocities disagree with its modes");
    // A surface's coefficients are always assembled (its advection is not evaluated tensor-free).
    const auto& q = c.quadrature;
    require(wellFormed(q.curl, 0) && wellFormed(q.velocityB, 0) && wellFormed(q.velocityC, 0) &&
                q.curl.rows() == 0 && q.velocityB.rows() == 0 && q.velocityC.rows() == 0 &&
                c.coefficients.storage != BasisCache::Coefficients::Storage::None &&
                c.windBase.empty() && c.windStokes.empty(),
            "its surface basis holds a vorticity quadrature, wind base flows or no coefficients");
    requireConsistentSpectrum(c, n, require);
}

/// A grid basis: cut-cell DEC on the grid's faces and cells, or closed-form descriptors.
void requireConsistentGrid(const BasisCache& c, const Require& require) {
    const std::int64_t cells = cellCount(c.grid, c.cellFraction.size());
    require(cells >= 0 && std::size_t(cells) == c.cellFraction.size(),
            "its grid is not a 2D or 3D grid with one fraction per cell");
    for (int axis = 0; axis < c.grid.dim; ++axis)
        require(std::isfinite(c.grid.boundsMin[axis]) && std::isfinite(c.grid.boundsMax[axis]) &&
                    c.grid.boundsMin[axis] < c.grid.boundsMax[axis],
                "its grid bounds are not an increasing pair of numbers on every axis");
    bool sidesHold = true;  // open sides: not across a periodic axis, none beyond dim
    for (int axis = 0; axis < 3; ++axis)
        if (c.grid.opensAxis(axis)) sidesHold &= axis < c.grid.dim && !c.grid.isPeriodic(axis);
    require(sidesHold, "an open side lies across a periodic axis or beyond the grid's dimension");
    require(known(c.wall) && known(c.boundary) && known(c.scalar.boundary) &&
                known(c.coefficients.storage),
            "a choice (wall, boundary or coefficient storage) is out of range");

    const auto& v = c.velocity;
    // A closed-form basis stores descriptors instead of columns.
    const bool closed = v.source == BasisSource::ClosedForm,
               closedScalar = c.scalar.source == BasisSource::ClosedForm;
    require(known(v.source) && known(c.scalar.source), "a basis source is out of range");
    const Eigen::Index n = closed ? Eigen::Index(v.separable.size()) : v.modes.cols();
    const Eigen::Index faceRows = closed ? Eigen::Index(c.faces.size()) : v.modes.rows();
    require(Eigen::Index(c.faces.size()) == faceRows && c.faceStar.size() == faceRows &&
                allBelow(c.faces, MacGrid::fromSpec(c.grid).faceTotal()) &&
                (closed ? v.modes.size() == 0 : v.separable.empty()),
            "its face degrees of freedom disagree with the grid or the velocity modes");
    require(
        separableWithinGrid(v.separable, c.grid) && separableWithinGrid(c.scalar.separable, c.grid),
        "a closed-form mode's wave numbers or phases lie outside its grid");
    require(Eigen::Index(c.cells.size()) == c.cellStar.size() && allBelow(c.cells, cells),
            "its cell degrees of freedom disagree with the grid");

    const auto& s = c.scalar;
    const Eigen::Index cellRows = closedScalar ? Eigen::Index(s.cells.size()) : s.modes.rows();
    const Eigen::Index scalarCount =
        closedScalar ? Eigen::Index(s.separable.size()) : s.modes.cols();
    require(Eigen::Index(s.cells.size()) == cellRows && s.cellStar.size() == cellRows &&
                s.eigenvalues.size() == scalarCount && allBelow(s.cells, cells) &&
                s.omittedConstants >= 0 &&
                (closedScalar ? s.modes.size() == 0 : s.separable.empty()),
            "its scalar modes disagree with their cells or eigenvalues");

    const auto& q = c.quadrature;
    const auto faces = std::int64_t(c.faces.size());
    require(wellFormed(q.curl, faces) && wellFormed(q.velocityB, faces) &&
                wellFormed(q.velocityC, faces) && q.velocityB.rows() == q.curl.rows() &&
                q.velocityC.rows() == q.curl.rows(),
            "its vorticity quadrature is not three maps of the same elements to its faces");
    // Wind base flows: none, or one finite face field (or none) per axis and direction of an
    // eigensolved basis, whose transport the quadrature evaluates.
    bool flowsHold = c.windBase.empty() || (c.windBase.size() == std::size_t(2 * c.grid.dim) &&
                                            !closed && q.curl.rows() > 0);
    flowsHold &= c.windStokes.size() == c.windBase.size();
    for (std::size_t f = 0; f < c.windBase.size() && flowsHold; ++f) {
        const std::vector<double>& flow = c.windBase[f];
        const std::vector<double>& stokes = c.windStokes[f];
        flowsHold &=
            flow.empty() || flow.size() == std::size_t(MacGrid::fromSpec(c.grid).faceTotal());
        flowsHold &= flow.empty() ? stokes.empty() : stokes.size() == std::size_t(n);
        for (const double u : flow) flowsHold &= std::isfinite(u);
        for (const double u : stokes) flowsHold &= std::isfinite(u);
    }
    require(flowsHold,
            "its wind base flows are not one finite face field per axis and direction, with one "
            "finite Stokes correction per mode");
    requireConsistentSpectrum(c, n, require);
}

}  // namespace

void requireConsistentCache(const BasisCache& c, const std::string& where) {
    const Require require = [&where](bool holds, const char* what) {
        if (!holds) throw Error(where + " is corrupt (" + what + ")");
    };
    if (c.kind == BasisKind::Surface)
        requireConsistentSurface(c, require);
    else
        requireConsistentGrid(c, require);
}

}  // namespace modeflow
