#include "tools/bench/BenchGrids.h"

#include <memory>
#include <tuple>

#include "tests/support/SyntheticBases.h"

namespace modeflow::bench {

const BasisCache& syntheticBasisFor(int dim, int cells, int modes) {
    static std::tuple<int, int, int> key{0, 0, 0};
    static std::unique_ptr<BasisCache> cache;
    if (!cache || key != std::tuple{dim, cells, modes}) {
        cache.reset();  // one 64³ basis of 200 modes is 1.2 GB
        cache = std::make_unique<BasisCache>(
            testing::syntheticBasis(testing::boxGrid(dim, cells), modes, 7));
        key = {dim, cells, modes};
    }
    return *cache;
}

void registerOnGrids(const std::vector<GridBenchmark>& benchmarks,
                     const std::function<void(benchmark::internal::Benchmark*)>& configure) {
    for (const BenchGrid& grid : kBenchGrids)
        for (const int modes : kBenchModes)
            for (const GridBenchmark& b : benchmarks)
                configure(benchmark::RegisterBenchmark(b.name.c_str(), b.run)
                              ->ArgNames({"dim", "cells", "N"})
                              ->Args({grid.dim, grid.cells, modes}));
}

}  // namespace modeflow::bench
