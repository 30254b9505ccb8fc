/// @file ConvergenceStudy.cpp
/// `convergence` (seed Fig. 6.13): the largest relative error of the first eigenvalues of the unit
/// disk and ball against their closed forms (ExactSpectra.h), over grid resolutions, for cut cells
/// and the staircase, velocity, Neumann and Dirichlet; each series with its fitted order.

#include <string>
#include <vector>

#include "precompute/Precompute.h"
#include "tools/validate/ExactSpectra.h"
#include "tools/validate/Fit.h"
#include "tools/validate/Studies.h"

namespace modeflow::validate {
namespace {

constexpr int kEigenvalues = 10;

/// The unit disk or ball in [−1.1, 1.1]^dim at `cells` per axis.
SceneSpec unitBall(int dim, int cells, BoundaryTreatment boundary, ScalarBoundary scalars) {
    SceneSpec scene;
    scene.name = "convergence";
    scene.grid.dim = dim;
    scene.grid.resolution = {cells, cells, dim == 3 ? cells : 1};
    scene.grid.boundsMin = {-1.1, -1.1, dim == 3 ? -1.1 : 0.0};
    scene.grid.boundsMax = {1.1, 1.1, dim == 3 ? 1.1 : 0.0};
    ShapeSpec ball;
    ball.kind = ShapeKind::Ball;
    ball.radius = 1.0;
    scene.domain = {ball};
    scene.basis.velocityModes = {{1, scalars == ScalarBoundary::Neumann ? kEigenvalues : 1}};
    scene.basis.scalarModes = kEigenvalues;
    scene.basis.scalarBoundary = scalars;
    scene.basis.boundary = boundary;
    return scene;
}

std::vector<double> values(const Eigen::VectorXd& v) {
    return {v.data(), v.data() + v.size()};
}

struct Series {
    std::string domain, boundary, field;
    int dim = 2;
    std::vector<double> resolution, h, error;
};

}  // namespace

StudyResult convergenceStudy(const StudyOptions& options) {
    struct Domain {
        const char* name;
        int dim;
        std::vector<int> cells;
    };
    const std::vector<Domain> domains =
        options.quick
            ? std::vector<Domain>{{"disk", 2, {32, 64}}, {"ball", 3, {10, 14}}}
            : std::vector<Domain>{{"disk", 2, {32, 64, 128, 256}}, {"ball", 3, {12, 16, 20, 24}}};
    const std::pair<BoundaryTreatment, const char*> boundaries[] = {
        {BoundaryTreatment::CutCell, "cut-cell"}, {BoundaryTreatment::Staircase, "staircase"}};
    const std::pair<SpectrumKind, const char*> fields[] = {{SpectrumKind::Velocity, "velocity"},
                                                           {SpectrumKind::Neumann, "neumann"},
                                                           {SpectrumKind::Dirichlet, "dirichlet"}};

    std::vector<Series> all;
    for (const Domain& domain : domains)
        for (const auto& [boundary, boundaryName] : boundaries) {
            Series series[3];
            for (int f = 0; f < 3; ++f)
                series[f] = {domain.name, boundaryName, fields[f].second, domain.dim, {}, {}, {}};
            for (const int cells : domain.cells) {
                options.note(std::string(domain.name) + " " + std::to_string(cells) + "^" +
                             std::to_string(domain.dim) + ", " + boundaryName);
                Progress quiet = Progress::silent();
                const BasisCache neumann =
                    ensureCache(unitBall(domain.dim, cells, boundary, ScalarBoundary::Neumann),
                                options.cacheDir, false, quiet)
                        .cache;
                const BasisCache dirichlet =
                    ensureCache(unitBall(domain.dim, cells, boundary, ScalarBoundary::Dirichlet),
                                options.cacheDir, false, quiet)
                        .cache;
                const std::vector<double> computed[3] = {values(neumann.velocity.eigenvalues),
                                                         values(neumann.scalar.eigenvalues),
                                                         values(dirichlet.scalar.eigenvalues)};
                for (int f = 0; f < 3; ++f) {
                    series[f].resolution.push_back(cells);
                    series[f].h.push_back(2.2 / cells);
                    series[f].error.push_back(maxRelativeError(
                        computed[f], unitBallSpectrum(domain.dim, fields[f].first, kEigenvalues)));
                }
            }
            all.insert(all.end(), std::begin(series), std::end(series));
        }

    StudyResult result;
    result.data["eigenvalues_compared"] = kEigenvalues;
    result.data["series"] = nlohmann::json::array();
    for (const Series& s : all) {
        const double order = logLogSlope(s.h, s.error);
        result.data["series"].push_back({{"domain", s.domain},
                                         {"dim", s.dim},
                                         {"boundary", s.boundary},
                                         {"field", s.field},
                                         {"resolution", s.resolution},
                                         {"h", s.h},
                                         {"max_relative_error", s.error},
                                         {"order", order}});
        if (s.domain == "disk" && s.boundary == "cut-cell" && s.field == "velocity")
            result.headline = {"fitted order, disk velocity eigenvalues, cut cells", order,
                               "at least 1.8 (second order)", order >= 1.8};
    }
    return result;
}

}  // namespace modeflow::validate
