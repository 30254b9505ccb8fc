#include "engine/reference/VelocityReconstruction.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacSampling.h"

namespace modeflow::reference {

std::vector<double> fluxesToFaceField(const BasisCache& cache, const Eigen::VectorXd& fluxes) {
    if (fluxes.size() != Eigen::Index(cache.faces.size()))
        throw Error("reconstruction: " + std::to_string(fluxes.size()) + " fluxes for a basis on " +
                    std::to_string(cache.faces.size()) + " faces");
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    std::vector<double> field(std::size_t(grid.faceTotal()), 0.0);
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const FaceLocation face = locateFace(grid, cache.faces[d]);
        field[std::size_t(cache.faces[d])] = fluxes[Eigen::Index(d)] / grid.faceArea(face.axis);
    }
    return field;
}

std::vector<double> reconstructFaceField(const VelocityBasis& basis, const Eigen::VectorXd& v) {
    return fluxesToFaceField(basis.cache(), basis.fluxes(v));
}

std::vector<double> reconstructFaceField(const BasisCache& cache, const Eigen::VectorXd& v) {
    return reconstructFaceField(VelocityBasis(cache), v);
}

std::vector<Vec3> cellCentreVelocity(const MacGrid& grid, std::span<const double> faceField) {
    requireFaceField(grid, faceField.size(), "cell-centre velocity");
    std::vector<Vec3> velocity(std::size_t(grid.cellCount()), Vec3{0.0, 0.0, 0.0});
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                Vec3& u = velocity[std::size_t(grid.cellIndex(x, y, z))];
                for (int a = 0; a < grid.dim; ++a)
                    u[a] = 0.5 * (faceField[grid.faceIndex(a, x, y, z)] +
                                  faceField[grid.upperFaceIndex(a, x, y, z)]);
            }
    return velocity;
}

std::vector<double> faceFieldDivergence(const MacGrid& grid, std::span<const double> faceField) {
    requireFaceField(grid, faceField.size(), "divergence");
    std::vector<double> divergence(std::size_t(grid.cellCount()), 0.0);
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                double outflow = 0.0;
                for (int a = 0; a < grid.dim; ++a)
                    outflow += (faceField[grid.upperFaceIndex(a, x, y, z)] -
                                faceField[grid.faceIndex(a, x, y, z)]) *
                               grid.faceArea(a);
                divergence[std::size_t(grid.cellIndex(x, y, z))] = outflow;
            }
    return divergence;
}

}  // namespace modeflow::reference
