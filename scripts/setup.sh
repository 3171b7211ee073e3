#!/usr/bin/env bash
# Installs coatfft's Debian 12 dependencies (idempotent, non-interactive) and builds in Release.
# Usage: scripts/setup.sh [build-dir]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}

# clang and libclang-rt-14-dev (libFuzzer and the sanitizer runtimes, only recommended by clang)
# are for scripts/fuzz.sh.
packages=(cmake g++ ninja-build pkg-config libfftw3-dev libeigen3-dev libgsl-dev libboost-dev
          catch2 libtomlplusplus-dev libcli11-dev nlohmann-json3-dev python3-numpy python3-matplotlib
          clang libclang-rt-14-dev)
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
