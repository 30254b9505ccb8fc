#include "tools/validate/PressureProjection.h"

#include <string>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"

namespace modeflow::validate {

std::vector<double> pressureProjection(const MacGrid& grid, std::span<const double> g) {
    requireFaceField(grid, g.size(), "pressure projection");
    for (int a = 0; a < grid.dim; ++a)
        if (grid.periodic[a])
            throw Error("pressure projection: closed boxes only (axis " + std::to_string(a) +
                        " is periodic)");
    // D: cells × faces, the net outflow through each cell's faces (box faces carry nothing).
    std::vector<Eigen::Triplet<double>> entries;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x)
                for (int a = 0; a < grid.dim; ++a) {
                    const std::array<int, 3> p{x, y, z};
                    const auto c = Eigen::Index(grid.cellIndex(x, y, z));
                    if (p[a] > 0)
                        entries.emplace_back(c, grid.faceIndex(a, x, y, z), -grid.faceArea(a));
                    if (p[a] + 1 < grid.cells[a])
                        entries.emplace_back(c, grid.upperFaceIndex(a, x, y, z), grid.faceArea(a));
                }
    Eigen::SparseMatrix<double> d(grid.cellCount(), grid.faceTotal());
    d.setFromTriplets(entries.begin(), entries.end());
    // Every face's dual volume is a cell's: the projection is orthogonal for the plain sum, and
    // D Dᵀ p = D g (singular along constant p only; D g has no constant part).
    const Eigen::SparseMatrix<double> laplacian = d * d.transpose();
    const Eigen::Map<const Eigen::VectorXd> gv(g.data(), Eigen::Index(g.size()));
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(1e-12);
    cg.setMaxIterations(20 * int(grid.cells[0] + grid.cells[1] + grid.cells[2]) + 1000);
    cg.compute(laplacian);
    const Eigen::VectorXd p = cg.solve(d * gv);
    if (cg.info() != Eigen::Success)
        throw Error("pressure projection: conjugate gradients did not converge (residual " +
                    std::to_string(cg.error()) + " after " + std::to_string(cg.iterations()) +
                    " iterations)");
    const Eigen::VectorXd u = gv - d.transpose() * p;
    return {u.data(), u.data() + u.size()};
}

}  // namespace modeflow::validate
