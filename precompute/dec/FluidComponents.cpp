#include "precompute/dec/FluidComponents.h"

#include <numeric>

namespace modeflow {
namespace {

std::int64_t root(std::vector<std::int64_t>& parent, std::int64_t i) {
    while (parent[std::size_t(i)] != i)
        i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
    return i;
}

}  // namespace

int FluidComponents::closedCount() const {
    int count = 0;
    for (std::size_t c = 0; c < of.size(); ++c) count += of[c] == std::int64_t(c) && !open[c];
    return count;
}

FluidComponents fluidComponents(const CutCellDec& dec) {
    FluidComponents parts;
    parts.of.resize(std::size_t(dec.cells.size()));
    std::iota(parts.of.begin(), parts.of.end(), std::int64_t(0));
    const SparseMatrix faceRows = dec.div.transpose();
    std::vector<std::int64_t> openFaceCells;  // a face on an open side has one cell
    for (std::int64_t f = 0; f < faceRows.outerSize(); ++f) {
        std::int64_t first = -1, cells = 0;
        for (SparseMatrix::InnerIterator it(faceRows, f); it; ++it, ++cells) {
            if (first < 0)
                first = it.col();
            else
                parts.of[std::size_t(root(parts.of, it.col()))] = root(parts.of, first);
        }
        if (cells == 1) openFaceCells.push_back(first);
    }
    for (std::size_t c = 0; c < parts.of.size(); ++c) parts.of[c] = root(parts.of, std::int64_t(c));
    parts.open.assign(parts.of.size(), false);
    for (const std::int64_t c : openFaceCells)
        parts.open[std::size_t(parts.of[std::size_t(c)])] = true;
    return parts;
}

}  // namespace modeflow
