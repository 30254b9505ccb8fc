#!/usr/bin/env bash
# Eigensolver benchmark: the velocity eigensolve of one scene (default scenes/bench/ball_48.toml)
# at several mode counts, with one shift-invert Lanczos run (Spectra), block Lanczos (`block`) and
# spectrum slicing (SLEPc) on 1 and on K MPI ranks, each from scratch in a throwaway cache folder. Prints the
# eigensolve's wall time, the process's CPU time (all ranks), peak memory per rank and the CPU
# seconds per mode. CPU time is the steadier figure on a shared machine.
# Usage: tools/bench-eigensolvers.sh [-n "100 200 400"] [-k RANKS] [-s "spectra block slepc mpi"] [SCENE]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
counts="100 200 400"
ranks=2
solvers="spectra block slepc mpi"
while getopts "n:k:s:" option; do
    case $option in
        n) counts=$OPTARG ;;
        k) ranks=$OPTARG ;;
        s) solvers=$OPTARG ;;
        *) echo "usage: $0 [-n COUNTS] [-k RANKS] [-s SOLVERS] [SCENE]" >&2; exit 1 ;;
    esac
done
shift $((OPTIND - 1))
scene=${1:-$root/scenes/bench/ball_48.toml}
modeflow="$root/build/tools/modeflow/modeflow"
[[ -x $modeflow ]] || { echo "bench-eigensolvers: build first (tools/build.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-7s %6s %6s %10s %10s %9s %12s %7s\n' solver ranks modes "solve [s]" "CPU [s]" "peak GiB" "CPU s/mode" factors
for n in $counts; do
    for solver in $solvers; do
        launch=() k=1 choice=$solver
        if [[ $solver == mpi ]]; then
            launch=(mpirun --allow-run-as-root --oversubscribe -n "$ranks") k=$ranks choice=slepc
        fi
        # The scene with its mode count and eigensolver replaced (velocity modes only).
        sed -e "s/^velocity_modes *=.*/velocity_modes = $n/" -e '/^eigensolver *=/d' \
            -e "s/^\[basis\]/[basis]\neigensolver = \"$choice\"/" "$scene" >"$work/scene.toml"
        /usr/bin/time -o "$work/time" -f '%U %S %M' "${launch[@]}" "$modeflow" precompute --force \
            --cache-dir "$work/cache" "$work/scene.toml" >/dev/null 2>"$work/log"
        read -r user system kb <"$work/time"
        solve=$(sed -n 's/^velocity eigensolve: \([0-9.]*\) s/\1/p' "$work/log")
        factors=$(sed -n 's/.*velocity: .* \([0-9]*\) factorizations\{0,1\} .*/\1/p' "$work/log")
        cpu=$(echo "$user + $system" | bc -l)
        printf '%-7s %6s %6s %10.1f %10.1f %9.2f %12.3f %7s\n' "$choice" "$k" "$n" "$solve" "$cpu" \
            "$(echo "$kb / 1048576" | bc -l)" "$(echo "$cpu / $n" | bc -l)" "${factors:--}"
        rm -rf "$work/cache"
    done
done
