#!/usr/bin/env bash
# The main job, set-up included: builds modeflow and runs the default scene end to end.
# Today that is the precompute (cached under $MODEFLOW_CACHE_DIR, default ~/.cache/modeflow)
# followed by a summary of the basis it produced.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
scene="${1:-$root/scenes/default.toml}"
"$root/build/tools/modeflow/modeflow" precompute "$scene"
"$root/build/tools/modeflow/modeflow" inspect "$scene"
