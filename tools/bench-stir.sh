#!/usr/bin/env bash
# Stir window benchmark: runs `modeflow stir` on the stir scenes (2D 128², 3D 32³, 100 modes each)
# for a fixed number of frames, one simulation step per frame, in the default window (and in any
# other size given), under Xvfb when there is no display, and prints frames per second with the
# wall time of a step and of a picture. With --offscreen the pictures are drawn but not shown
# (`stir --offscreen`: no display or Xvfb needed, e.g. on a headless GPU; no presentation cost).
# Usage: tools/bench-stir.sh [--offscreen] [FRAMES [DEVICE [WIDTHxHEIGHT...]]]
#        (DEVICE: cpu, vulkan or an index)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh" >/dev/null 2>&1 || { echo "bench-stir: build failed (run tools/build.sh)" >&2; exit 1; }
modeflow="$root/build/tools/modeflow/modeflow"
offscreen=()
[[ ${1:-} != --offscreen ]] || { offscreen=(--offscreen); shift; }
frames=${1:-200}
device=${2:-vulkan}
sizes=("default" "${@:3}")
window=()
[[ -n ${DISPLAY:-} || -n ${offscreen[*]} ]] || window=(xvfb-run -a -s "-screen 0 1280x720x24 -noreset")
export MODEFLOW_CACHE_DIR=${MODEFLOW_CACHE_DIR:-$root/build/bench-cache}

printf '| scene | window | frames | fps | ms per step | ms per picture | device |\n|---|---|---|---|---|---|---|\n'
for scene in stir_2d stir_3d; do
    "$modeflow" precompute "$root/scenes/$scene.toml" >/dev/null 2>&1
    for size in "${sizes[@]}"; do
        extent=()
        [[ $size == default ]] || extent=(--width "${size%x*}" --height "${size#*x}")
        log=$("${window[@]}" "$modeflow" stir "$root/scenes/$scene.toml" --frames "$frames" \
            --device "$device" "${offscreen[@]}" "${extent[@]}" 2>&1)
        name=$(echo "$log" | sed -n 's/^chosen *#[0-9]* \(.*\) (.*/\1/p' | head -n 1)
        echo "$log" | sed -n "s|^\([0-9]*\) frames (\([0-9x]*\)) in .*: \([0-9.]*\) fps, [0-9]* steps, \([0-9.]*\) ms per step, \([0-9.]*\) ms per picture|\| $scene \| \2 \| \1 \| \3 \| \4 \| \5 \| $name \||p"
    done
done
