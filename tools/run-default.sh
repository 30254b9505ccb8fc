#!/usr/bin/env bash
# The main job, set-up included: builds the modeflow binary (no tests, no benchmarks) and runs the default scene end to end: the
# precompute (cached under $MODEFLOW_CACHE_DIR, default ~/.cache/modeflow), then the simulation on
# the first Vulkan device (lavapipe without a GPU), writing one OpenVDB file per frame (and PNG
# previews) to frames/NAME/. Usage: tools/run-default.sh [SCENE [extra `modeflow run` options]]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh" modeflow
scene="${1:-$root/scenes/default.toml}"
shift || true
name=$(basename "$scene" .toml)
"$root/build/tools/modeflow/modeflow" inspect "$scene"
"$root/build/tools/modeflow/modeflow" run "$scene" --out "$root/frames/$name" "$@"
