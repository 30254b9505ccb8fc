#pragma once
/// @file ParallelRows.h
/// Threading shared by the coefficient storages: the pair rows are cut into one contiguous range
/// per thread (equal work, so equal bytes streamed), each thread accumulates into its own zeroed
/// buffer, and the buffers are summed. Contiguous ranges keep each thread's reads sequential, and
/// the fixed split keeps results reproducible for a given thread count.

#include <cstddef>
#include <vector>

#include <omp.h>

namespace modeflow {

/// Threads worth using for a contraction streaming `bytes`: below about half a megabyte the
/// fork/join costs more than it saves.
inline int contractionThreads(std::size_t bytes) {
    constexpr std::size_t minBytesForThreads = std::size_t(1) << 19;
    return bytes < minBytesForThreads ? 1 : omp_get_max_threads();
}

/// Row bounds b[0..threads] with workBefore(b[t]) ≈ t·total/threads; workBefore is non-decreasing.
template <class WorkBefore>
std::vector<std::size_t> splitRows(std::size_t rows, int threads, WorkBefore workBefore) {
    std::vector<std::size_t> bounds(threads + 1, rows);
    bounds[0] = 0;
    const double total = double(workBefore(rows));
    for (int t = 1; t < threads; ++t) {
        const double target = total * t / threads;
        std::size_t lo = bounds[t - 1], hi = rows;
        while (lo < hi) {
            const std::size_t mid = (lo + hi) / 2;
            if (double(workBefore(mid)) < target)
                lo = mid + 1;
            else
                hi = mid;
        }
        bounds[t] = lo;
    }
    return bounds;
}

/// Runs body(begin, end, acc) for each range of `bounds` in parallel and leaves in `result` the sum
/// of the accumulators; `result` must be zeroed with its final shape by the caller.
template <class Accumulator, class Body>
void reduceOverRows(const std::vector<std::size_t>& bounds, Accumulator& result, Body body) {
    const int threads = int(bounds.size()) - 1;
    if (threads == 1) {
        body(bounds[0], bounds[1], result);
        return;
    }
    std::vector<Accumulator> partial(threads - 1);
#pragma omp parallel for num_threads(threads) schedule(static, 1)
    for (int t = 0; t < threads; ++t) {
        if (t == 0) {
            body(bounds[0], bounds[1], result);
        } else {
            partial[t - 1] = Accumulator::Zero(result.rows(), result.cols());
            body(bounds[t], bounds[t + 1], partial[t - 1]);
        }
    }
    for (const Accumulator& p : partial) result += p;
}

}  // namespace modeflow
