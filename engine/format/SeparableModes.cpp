#include "engine/format/SeparableModes.h"

#include <cmath>

#include "engine/core/MacGrid.h"

namespace modeflow {

double separableFactor(const GridSpec& grid, int axis, int wave, int shift, int twiceX, bool sine) {
    // θx + φ − (sine ? π/2 : 0) = π m / (2n).
    const std::int64_t n = grid.resolution[axis];
    const std::int64_t turn = 4 * n;
    std::int64_t m =
        std::int64_t(wave) * twiceX * (grid.isPeriodic(axis) ? 2 : 1) + n * shift - (sine ? n : 0);
    m = ((m % turn) + turn) % turn;
    if (m % n == 0) {
        constexpr double kQuarter[4] = {1.0, 0.0, -1.0, 0.0};
        return kQuarter[m / n];
    }
    return std::cos(M_PI * double(m) / double(2 * n));
}

double axisSigma(const GridSpec& grid, int axis, int wave) {
    const double theta = (grid.isPeriodic(axis) ? 2.0 : 1.0) * M_PI * wave / grid.resolution[axis];
    return 2.0 / grid.spacing(axis) * std::sin(0.5 * theta);
}

std::vector<std::int64_t> wholeBoxFaces(const GridSpec& grid) {
    const MacGrid mac = MacGrid::fromSpec(grid);
    std::vector<std::int64_t> faces;
    for (int a = 0; a < grid.dim; ++a) {
        const std::array<int, 3> e = mac.faceExtent(a);
        const int first = grid.isPeriodic(a) ? 0 : 1;
        const int last = grid.resolution[a] - 1;  // a wall at n_a; on a periodic axis, face 0 again
        for (int z = 0; z < e[2]; ++z)
            for (int y = 0; y < e[1]; ++y)
                for (int x = 0; x < e[0]; ++x) {
                    const std::array<int, 3> p{x, y, z};
                    if (p[a] >= first && p[a] <= last) faces.push_back(mac.faceIndex(a, x, y, z));
                }
    }
    return faces;
}

namespace {

/// One axis factor at positions 0..count−1 (+½ when `half`).
std::vector<double> factorTable(const GridSpec& grid, int axis, const SeparableMode& mode,
                                int count, bool half, bool sine) {
    std::vector<double> t(std::size_t(count), 1.0);
    if (axis >= grid.dim) return t;
    for (int x = 0; x < count; ++x)
        t[std::size_t(x)] = separableFactor(grid, axis, mode.wave[axis], mode.shift[axis],
                                            2 * x + (half ? 1 : 0), sine);
    return t;
}

}  // namespace

Eigen::MatrixXd velocityModeFluxes(const GridSpec& grid, const std::vector<std::int64_t>& faces,
                                   const std::vector<SeparableMode>& modes) {
    const MacGrid mac = MacGrid::fromSpec(grid);
    // Each face's normal axis and position, decoded once.
    struct Place {
        int normal;
        std::array<int, 3> pos;
    };
    std::vector<Place> places(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
        int normal = 0;
        while (normal + 1 < grid.dim && faces[f] >= mac.faceOffset(normal + 1)) ++normal;
        const std::array<int, 3> e = mac.faceExtent(normal);
        std::int64_t local = faces[f] - mac.faceOffset(normal);
        places[f].normal = normal;
        places[f].pos[0] = int(local % e[0]);
        local /= e[0];
        places[f].pos[1] = int(local % e[1]);
        places[f].pos[2] = int(local / e[1]);
    }
    std::array<double, 3> area{};
    for (int a = 0; a < grid.dim; ++a) area[a] = mac.faceArea(a);

    Eigen::MatrixXd out(Eigen::Index(faces.size()), Eigen::Index(modes.size()));
#pragma omp parallel for schedule(dynamic)
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const SeparableMode& mode = modes[m];
        // sine[a]: s_a at whole positions (the normal factor); cosine[a]: f_a at half positions.
        std::array<std::vector<double>, 3> sine, cosine;
        for (int a = 0; a < 3; ++a) {
            const int n = grid.resolution[a];
            sine[a] = factorTable(grid, a, mode, n + 1, false, true);
            cosine[a] = factorTable(grid, a, mode, n, true, false);
        }
        auto column = out.col(Eigen::Index(m));
        for (std::size_t f = 0; f < faces.size(); ++f) {
            const Place& p = places[f];
            double value = mode.amplitude[p.normal] * area[p.normal];
            for (int a = 0; a < 3; ++a)
                value *= a == p.normal ? sine[a][std::size_t(p.pos[a])]
                                       : cosine[a][std::size_t(p.pos[a])];
            column[Eigen::Index(f)] = value;
        }
    }
    return out;
}

Eigen::MatrixXd scalarModeValues(const GridSpec& grid, const std::vector<std::int64_t>& cells,
                                 const std::vector<SeparableMode>& modes) {
    const MacGrid mac = MacGrid::fromSpec(grid);
    Eigen::MatrixXd out(Eigen::Index(cells.size()), Eigen::Index(modes.size()));
#pragma omp parallel for schedule(dynamic)
    for (std::size_t m = 0; m < modes.size(); ++m) {
        std::array<std::vector<double>, 3> cosine;
        for (int a = 0; a < 3; ++a)
            cosine[a] = factorTable(grid, a, modes[m], grid.resolution[a], true, false);
        const double scale = modes[m].amplitude[0] * mac.cellVolume();
        for (std::size_t c = 0; c < cells.size(); ++c) {
            std::int64_t local = cells[c];
            const auto x = std::size_t(local % mac.cells[0]);
            local /= mac.cells[0];
            const auto y = std::size_t(local % mac.cells[1]);
            const auto z = std::size_t(local / mac.cells[1]);
            out(Eigen::Index(c), Eigen::Index(m)) =
                scale * cosine[0][x] * cosine[1][y] * cosine[2][z];
        }
    }
    return out;
}

}  // namespace modeflow
