#pragma once
/// @file BenchGrids.h
/// The grids and mode counts of the runtime stage and basis kernel tables (2D 256², 3D 48³ and
/// 64³; N = 50, 100, 200), on synthetic bases (tests/support/SyntheticBases.h: random
/// ⋆-orthonormal modes on every interior face, random coefficients): a stage's speed does not
/// depend on the basis being an eigenbasis, and a 64³ eigenbasis takes minutes to compute.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/format/BasisCache.h"

namespace modeflow::bench {

struct BenchGrid {
    int dim, cells;
};
inline constexpr std::array<BenchGrid, 3> kBenchGrids{BenchGrid{2, 256}, BenchGrid{3, 48},
                                                      BenchGrid{3, 64}};
inline constexpr std::array<int, 3> kBenchModes{50, 100, 200};

/// The synthetic basis of `modes` modes on the box grid (SyntheticBases.h's boxGrid), kept
/// until another is asked for (benchmarks of one size run one after another).
const BasisCache& syntheticBasisFor(int dim, int cells, int modes);

struct GridBenchmark {
    std::string name;
    std::function<void(benchmark::State&)> run;
};

/// Registers each benchmark for every grid and mode count as NAME/dim:D/cells:C/N:M with the
/// arguments {dim, cells, N}, size by size (so each synthetic basis is made once);
/// `configure` adds what the table needs (iterations, time).
void registerOnGrids(const std::vector<GridBenchmark>& benchmarks,
                     const std::function<void(benchmark::internal::Benchmark*)>& configure);

}  // namespace modeflow::bench
