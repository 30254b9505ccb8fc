#!/usr/bin/env bash
# The Vulkan runtime's benchmark tables (engine/README.md "Speed"), one Google Benchmark executable each:
# contraction, whole modal steps, the runtime step by stage, the basis kernels alone, smoke
# advection, the 3D preview, the 64³ closed-form box stage by stage (CPU reference and device),
# and dense against tensor-free steps (N up to 1000: 10 GB, minutes).
# Arguments go to every table: `--device N` picks the Vulkan device (`vulkaninfo --summary`),
# Google Benchmark's own flags (--benchmark_filter=REGEX, --benchmark_repetitions=N,
# --benchmark_format=csv, ...) work as usual, anything else is refused.
# Usage: tools/bench-runtime.sh [--device N] [--benchmark_...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh" >/dev/null 2>&1 || { echo "bench-runtime: build failed (run tools/build.sh)" >&2; exit 1; }
for table in contraction modal_steps runtime_stages basis_kernels smoke_advection preview closed_form tensor_free; do
    "$root/build/tools/bench/bench_$table" "$@"
done
