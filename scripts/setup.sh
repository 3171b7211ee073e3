#!/usr/bin/env bash
# Installs coatfft's Debian 12 dependencies (idempotent, non-interactive), builds in Release and
# makes the Python module importable by Debian's python3 from any directory (docs/python.md).
# Usage: scripts/setup.sh [build-dir]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}

# clang and libclang-rt-14-dev (libFuzzer and the sanitizer runtimes, only recommended by clang)
# are for scripts/fuzz.sh; python3-dev and pybind11 build the Python module, pytest tests it, and
# pip, setuptools and wheel install it as a package (the packaging test); NetCDF, libzip and
# tinyxml2 read and write measured topographies (topography/), python3-netcdf4 writes the test files;
# Open MPI and FFTW's MPI library run the distributed operators and solves, NetCDF's PnetCDF build
# writes their NetCDF files collectively (docs/scale.md).
packages=(cmake g++ ninja-build pkg-config libfftw3-dev libeigen3-dev libgsl-dev libboost-dev
          catch2 libtomlplusplus-dev libcli11-dev nlohmann-json3-dev python3-numpy python3-matplotlib
          clang libclang-rt-14-dev python3-dev pybind11-dev python3-pybind11 python3-pytest
          python3-pip python3-setuptools python3-wheel libnetcdf-dev libzip-dev libtinyxml2-dev
          python3-netcdf4 libfftw3-mpi-dev libopenmpi-dev openmpi-bin libnetcdf-pnetcdf-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -q
  $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release ${COATFFT_CMAKE_ARGS:-}
cmake --build "$build_dir" -j "$(nproc)"

# The module of this build for Debian's python3, from any directory: a .pth file in the user's
# site-packages naming build/python (rewritten by each setup of a build that has the module;
# sanitized builds have none). PYTHONPATH=build/python works as well, without it.
module_dir="$(pwd)/$build_dir/python"
if compgen -G "$module_dir/coatfft/_coatfft*.so" > /dev/null; then
  site_dir=$(/usr/bin/python3 -m site --user-site)
  mkdir -p "$site_dir"
  echo "$module_dir" > "$site_dir/coatfft-build.pth"
  echo "setup.sh: import coatfft now finds $module_dir (through $site_dir/coatfft-build.pth)"
fi
