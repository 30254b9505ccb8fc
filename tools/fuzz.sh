#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz into build-fuzz/ (clang++, ASan + UBSan, only the
# libraries they read through) and runs each for SECONDS (default 60) on its seeds
# (tests/fuzz/corpus/<target>, the scenes, tests/fuzz/regressions/<target>) and on a scratch corpus
# kept between runs in build-fuzz/tests/fuzz/run/<target>/corpus. Prints one row per target:
# seconds run, executions, coverage (edges after the seeds -> at the end, new inputs kept) and
# findings. A finding stops its target and leaves the input in
# build-fuzz/tests/fuzz/run/<target>/findings/; the script then exits 1. Fix it, and keep the
# input as a regression test: copy it to tests/fuzz/regressions/<target>/ (FuzzRegressionTest
# replays every file there). `tools/fuzz.sh --build-only` only builds (tools/run-tests.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
seconds=10
build_only=0
case "${1:-60}" in
    --build-only) build_only=1 ;;
    *[!0-9]* | "") echo "usage: tools/fuzz.sh [SECONDS | --build-only]" >&2; exit 2 ;;
    *) seconds=${1:-60} ;;
esac

"$root/tools/install-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
    -DMODEFLOW_FUZZ=ON -DMODEFLOW_FUZZ_SECONDS="$seconds" -DMODEFLOW_BUILD_TESTS=OFF \
    -DMODEFLOW_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" --target modeflow_fuzz_targets -j "$(nproc)"
((build_only)) && exit 0

targets=(SceneLoader CacheReader ObjReader CheckpointReader InputScript)
rows=() failed=0
for target in "${targets[@]}"; do
    run="$build/tests/fuzz/run/$target"
    log="$run/last.log"
    rm -f "$run/findings/"*
    rm -rf "${run:?}/tmp/"*  # scratch folders a crashed run left behind
    start=$(date +%s)
    (cd "$build" && ctest -R "^fuzz_${target}\$" -V >"$log" 2>&1) || failed=1
    elapsed=$(($(date +%s) - start))
    stat() { grep -o "stat::$1: *[0-9]*" "$log" | grep -o '[0-9]*$' | tail -n 1; }
    covered() { grep -o "$1.*cov: [0-9]*" "$log" | grep -o '[0-9]*$' | "$2" -n 1; }
    findings=$(find "$run/findings" -type f | wc -l)
    rows+=("$(printf '%-17s %8s %12s %10s %8s   %s' "$target" "$elapsed" "$(stat number_of_executed_units)" \
        "$(covered INITED head) -> $(covered '#' tail)" "$(stat new_units_added)" \
        "$( ((findings)) && echo "$findings: $(ls "$run/findings")" || echo none)")")
done
printf '%-17s %8s %12s %10s %8s   %s\n' target seconds executions "coverage" "new" findings
printf '%s\n' "${rows[@]}"
((failed == 0)) || { echo "a target failed: see build-fuzz/tests/fuzz/run/<target>/last.log" >&2; exit 1; }
