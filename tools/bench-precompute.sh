#!/usr/bin/env bash
# Precompute benchmark: times each scene in scenes/bench (or the scenes given) from scratch, in a
# throwaway cache folder, and prints a table of wall time, peak memory and eigensolve statistics.
# Usage: tools/bench-precompute.sh [SCENE...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh" >/dev/null 2>&1 || { echo "bench-precompute: build failed (run tools/build.sh)" >&2; exit 1; }
modeflow="$root/build/tools/modeflow/modeflow"
scenes=("$@")
((${#scenes[@]})) || scenes=("$root"/scenes/bench/*.toml)
cache=$(mktemp -d)
trap 'rm -rf "$cache"' EXIT

printf '%-16s %9s %6s %9s %9s %10s %8s %8s\n' scene dofs modes "wall [s]" "peak GiB" "vel solves" "factor" "solves"
for scene in "${scenes[@]}"; do
    log="$cache/log"
    /usr/bin/time -f 'TIME %e %M' "$modeflow" precompute --force --cache-dir "$cache" "$scene" \
        >"$cache/out" 2>"$log"
    path=$(tail -n 1 "$cache/out")
    read -r wall kb < <(awk '/^TIME/ {print $2, $3}' "$log")
    solves=$(sed -n 's/.*velocity: \([0-9]*\) shift-invert solves.*/\1/p' "$log")
    json=$("$modeflow" inspect "$path" --json)
    dofs=$(echo "$json" | sed -n 's/.*"faces":\([0-9]*\).*/\1/p')
    modes=$(echo "$json" | sed -n 's/.*"velocity":{"count":\([0-9]*\).*/\1/p')
    factor=$(echo "$json" | sed -n 's/.*"velocity_factorization":\([0-9.e+-]*\).*/\1/p')
    vsolves=$(echo "$json" | sed -n 's/.*"velocity_solves":\([0-9.e+-]*\).*/\1/p')
    printf '%-16s %9s %6s %9.1f %9.2f %10s %8.1f %8.1f\n' "$(basename "$scene" .toml)" "$dofs" "$modes" \
        "$wall" "$(echo "$kb / 1048576" | bc -l)" "${solves:-dense}" "${factor:-0}" "${vsolves:-0}"
    rm -f "$path"
done
