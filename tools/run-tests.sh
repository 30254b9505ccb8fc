#!/usr/bin/env bash
# Builds modeflow and runs the whole test suite (set-up included). Extra arguments go to ctest,
# e.g. `tools/run-tests.sh -LE slow` or `-R Cli`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j "$(nproc)" "$@"
