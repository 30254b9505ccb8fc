#!/usr/bin/env bash
# Configures and builds modeflow (Release) into ./build, installing missing packages first.
# Arguments name the targets to build (default: all of them, tests and benchmarks included);
# tools/run-default.sh builds the `modeflow` binary alone.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install-deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$root/build" -j "$(nproc)" "${targets[@]}"
