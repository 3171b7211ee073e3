#!/usr/bin/env bash
# coatfft as a package, checked as its users meet it. Usage:
#   check.sh install   BUILD_DIR  installs BUILD_DIR into a temporary prefix, moves the prefix
#                                 (relocatable), checks that no installed header includes a
#                                 private dependency, that it holds exactly the public headers
#                                 and that no installed file names the build
#                                 machine's source or build tree, then builds and runs
#                                 examples/minimal.cpp with find_package(coatfft).
#   check.sh subdirectory         builds and runs examples/minimal.cpp in a project that adds
#                                 this source tree with add_subdirectory.
#   check.sh subdirectory-configure   only configures that project: its assertions (the
#                                 consumer's build type left alone, no source include root)
#                                 are configure-time.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)

case "${1:-}" in
  install)
    build=$(cd "$2" && pwd)
    cmake --install "$build" --prefix "$work/staged" >/dev/null
    mv "$work/staged" "$work/moved"
    prefix=$work/moved
    # No installed header may include FFTW, GSL, Boost or toml++ (they are private dependencies).
    if grep -rnE '#\s*include\s*[<"](fftw3|gsl/|boost/|toml\+\+)' "$prefix/include"; then
      echo "FAIL: an installed header includes a private dependency" >&2; exit 1
    fi
    # That each public header compiles on its own is the build's target coatfft_header_check
    # (cmake/coatfft_package.cmake); here, that the install holds exactly those headers.
    installed=$(cd "$prefix/include" && find coatfft -name '*.hpp' | sort)
    linked=$(cd "$build/include" && find coatfft -name '*.hpp' | sort)
    [ "$installed" = "$linked" ] ||
      { echo "FAIL: the installed headers differ from the public ones" >&2; exit 1; }
    if grep -rlF -e "$root" -e "$build" "$prefix"; then
      echo "FAIL: the install names the build machine's paths (not relocatable)" >&2; exit 1
    fi
    test -x "$prefix/bin/coatfft" || { echo "FAIL: the coatfft program is not installed" >&2; exit 1; }
    cmake -S "$here" -B "$work/consumer" "${generator[@]}" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release >/dev/null
    ;;
  subdirectory | subdirectory-configure)
    # No build type: coatfft must not impose its own (the consumer's stays empty). The library
    # is built once here: as a unity build.
    cmake -S "$here" -B "$work/consumer" "${generator[@]}" -DCOATFFT_SOURCE_DIR="$root" \
      -DCOATFFT_UNITY=ON >/dev/null
    [ "$1" = subdirectory ] || { echo "the add_subdirectory consumer configures"; exit 0; }
    ;;
  *)
    echo "usage: $0 install BUILD_DIR | subdirectory | subdirectory-configure" >&2; exit 2 ;;
esac
cmake --build "$work/consumer" -j "$(nproc)" >/dev/null
"$work/consumer/minimal"
