#!/usr/bin/env bash
# Builds modeflow and runs the whole test suite (set-up included). Extra arguments go to ctest,
# e.g. `tools/run-tests.sh -LE slow` or `-R Cli`. Without arguments the tests that may open a
# Vulkan context (label vulkan) then run a second time with the Khronos validation layer forced on
# for every context (MODEFLOW_VULKAN_VALIDATION=1); they fail on any validation message. Left out
# of that pass: the kernel tests' /Plain and /Validated instances (the suite already ran them
# with the layer), the slow tests (the slow window tests force the layer themselves, the others
# are CPU-bound) and the shipped scenes (their device paths are the kernel and CLI tests').
# Where clang++ can link libFuzzer, the fuzz targets of tests/fuzz are built too (build-fuzz/, by
# tools/fuzz.sh) and each runs for 10 s on its seeds (label fuzz), so a target that stops building
# or starts failing is noticed; the inputs they once failed on are replayed in every build
# (FuzzRegressionTest).
#
# `tools/run-tests.sh --sanitize [CTEST ARGS]` instead builds into build-asan/ with
# AddressSanitizer and UndefinedBehaviorSanitizer (MODEFLOW_SANITIZE=ON) and runs the whole
# suite there; any finding fails its test. CI (.ci/run) runs both.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = --sanitize ]; then
    shift
    "$root/tools/install-deps.sh"
    # clang++ (installed for the fuzz targets): it compiles the sanitized objects in half g++'s
    # time (59 objects: 146 s against 288 s), as fast as g++ compiles them unsanitized.
    cmake -S "$root" -B "$root/build-asan" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
        -DMODEFLOW_SANITIZE=ON -DMODEFLOW_BUILD_BENCHMARKS=OFF >/dev/null
    cmake --build "$root/build-asan" -j "$(nproc)"
    cd "$root/build-asan"
    exec ctest --output-on-failure -j "$(nproc)" "$@"
fi
"$root/tools/build.sh"
fuzz=0
if "$root/tools/fuzz.sh" --available; then
    "$root/tools/fuzz.sh" --build-only
    fuzz=1
else
    echo "== clang++ cannot link libFuzzer here: the fuzz targets' short runs are left out =="
fi
cd "$root/build"
ctest --output-on-failure -j "$(nproc)" "$@"
if ((fuzz)); then
    echo "== the fuzz targets, 10 s each (build-fuzz/, label fuzz) =="
    (cd "$root/build-fuzz" && ctest --output-on-failure -j "$(nproc)" "$@")
fi
if [ $# -eq 0 ]; then
    echo "== again with the Vulkan validation layer on every context =="
    MODEFLOW_VULKAN_VALIDATION=1 ctest --output-on-failure -j "$(nproc)" -L vulkan -LE "slow|scenes" \
        -E "/(Plain|Validated)"
fi
