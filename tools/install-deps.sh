#!/usr/bin/env bash
# Installs the Debian 12 packages modeflow builds and runs with, only those that are missing.
# Safe to run again: with everything present it does nothing.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config ccache
    libeigen3-dev libspectra-dev libsuitesparse-dev libopenblas0-pthread libfftw3-dev
    slepc-dev petsc-dev         # sliced eigensolves: SLEPc, PETSc with MUMPS, Open MPI (mpirun)
    libopenvdb-dev libboost-iostreams-dev libtbb-dev
    libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libtinyobjloader-dev libxxhash-dev
    libvulkan-dev mesa-vulkan-drivers vulkan-tools glslang-tools spirv-tools vulkan-validationlayers
    libglfw3-dev xvfb xauth
    libstb-dev libgtest-dev libbenchmark-dev time bc python3 clang-format  # tools/check-layering.py, tools/check-format.sh
    clang libclang-rt-14-dev    # the fuzz targets (libFuzzer), tools/fuzz.sh
    python3-matplotlib          # modeflow validate draws its figures with it
    pybind11-dev python3-dev python3-numpy python3-pytest python3-openvdb  # the Python module, its tests
    blender                     # the add-on's test bakes and renders in it (headless)
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
((${#missing[@]} == 0)) && exit 0

sudo=""
if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
