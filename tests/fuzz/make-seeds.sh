#!/usr/bin/env bash
# Regenerates the binary seeds of the cache and checkpoint fuzz targets (tests/fuzz/corpus/
# CacheReader, CheckpointReader) with a built modeflow: tiny bases and one-frame runs, a few KiB
# each. Run it after a change of either format, e.g. `tests/fuzz/make-seeds.sh build/tools/modeflow/modeflow`.
set -euo pipefail
modeflow=$(realpath "${1:?usage: make-seeds.sh path/to/modeflow}")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scene() {  # name, grid lines, extra sections
    printf '%s\n[basis]\nvelocity_modes = %s\nscalar_modes = 1\n%s\n[output]\nframes = 1\nsteps_per_frame = 1\n' \
        "$2" "$3" "$4" >"$work/$1.toml"
}
disk='[grid]
resolution = [6, 6]
bounds_min = [-1.1, -1.1]
bounds_max = [1.1, 1.1]
[[domain]]
shape = "ball"
center = [0.0, 0.0]
radius = 1.0'
box='[grid]
resolution = [3, 3, 3]
bounds_min = [-1.0, -1.0, -1.0]
bounds_max = [1.0, 1.0, 1.0]
[[domain]]
shape = "box"
min = [-0.9, -0.9, -0.9]
max = [0.9, 0.9, 0.9]'
# The whole grid box with free-slip walls: closed-form bases (descriptors, sparse coefficients).
wholebox='[grid]
resolution = [4, 3, 3]
bounds_min = [0.0, 0.0, 0.0]
bounds_max = [1.0, 1.0, 1.0]'
smoke='[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.3
density = 1.0
temperature = 1.0
[smoke]
buoyancy = 1.0'
# Particles: the checkpoint holds their positions, velocities and sets.
scene disk "$disk" 3 "$smoke
[[particles]]
shape = \"ball\"
center = [0.0, 0.3]
radius = 0.3
count = 6
[[particles]]
shape = \"box\"
min = [-0.4, -0.2]
max = [0.4, 0.2]
rate = 100
drag = 2"
scene disk_mhd "$disk" 3 '[simulation]
mhd = true
[initial]
velocity = "random"
magnetic_energy = 0.5'
# The linearized rule: its checkpoints hold the rate carried between steps.
scene disk_linearized "$disk" 3 "$smoke
[simulation]
integrator = \"linearized\"
[initial]
velocity = \"random\""
# Fire: its checkpoints hold the fuel and the flame.
scene disk_fire "$disk" 3 '[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.3
temperature = 1.0
fuel = 4.0
[fire]
ignition = 0.1'
scene box "$box" 4 ""
scene wholebox "$wholebox" 6 ""
# Open sides: the grid's open flags, an eigensolved whole box.
scene openbox "$wholebox
open = [\"x_min\", \"z_max\"]" 6 ""
# A fluid on an icosahedron's surface: a surface basis (mesh, edges, advection, vertex velocities).
t=1.618033988749895
printf 'v %s\n' "-1 $t 0" "1 $t 0" "-1 -$t 0" "1 -$t 0" "0 -1 $t" "0 1 $t" "0 -1 -$t" "0 1 -$t" \
    "$t 0 -1" "$t 0 1" "-$t 0 -1" "-$t 0 1" >"$work/icosahedron.obj"
printf 'f %s\n' "1 12 6" "1 6 2" "1 2 8" "1 8 11" "1 11 12" "2 6 10" "6 12 5" "12 11 3" "11 8 7" \
    "8 2 9" "4 10 5" "4 5 3" "4 3 7" "4 7 9" "4 9 10" "5 10 6" "3 5 12" "7 3 11" "9 7 8" "10 9 2" \
    >>"$work/icosahedron.obj"
scene surface "[surface]
mesh = \"icosahedron.obj\"" 4 ""
# No tensor, only the vorticity quadrature (the extra line lands in [basis]).
scene disk_tensor_free "$disk" 3 'coefficients = "tensor-free"'

caches="$here/corpus/CacheReader" checkpoints="$here/corpus/CheckpointReader"
mkdir -p "$caches" "$checkpoints"
for name in disk box wholebox openbox surface disk_tensor_free; do
    # A folder per scene: disk and disk_tensor_free share their basis key.
    cache=$("$modeflow" precompute "$work/$name.toml" --cache-dir "$work/cache_$name" 2>/dev/null | tail -n 1)
    cp "$cache" "$caches/$name.mfbasis"
    # The payload alone: the target wraps inputs without the magic in a valid header and checksum.
    size=$(stat -c %s "$cache")
    tail -c +41 "$cache" | head -c $((size - 48)) >"$caches/$name.payload"
done
# The device's midpoint rule (lavapipe will do): its checkpoints hold the warm start's R and the
# substep schedule.
cp "$work/disk.toml" "$work/disk_device.toml"
for name in disk disk_mhd disk_linearized disk_device disk_fire; do
    device=cpu
    [ "$name" = disk_device ] && device=vulkan
    "$modeflow" run "$work/$name.toml" --device $device --cache-dir "$work/cache" --out "$work/$name" >/dev/null 2>&1
    cp "$work/$name/$name.resume" "$checkpoints/$name.resume"
    # The body after magic and version, without the checksum (wrapped again by the target).
    size=$(stat -c %s "$work/$name/$name.resume")
    tail -c +21 "$work/$name/$name.resume" | head -c $((size - 28)) >"$checkpoints/$name.body"
done
ls -l "$caches" "$checkpoints"
