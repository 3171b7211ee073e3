#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) in build-fuzz and runs each for
# SECONDS seconds on a copy of its seed corpus (fuzz/corpus/TARGET), so the repository is left as
# it is; the targets run side by side, as many at a time as there are cores. Prints one line per
# target and exits non-zero if any target found a crash, a sanitizer report or an exception other
# than InvalidArgument; its input is kept under build-fuzz/fuzz/run/findings/TARGET/, the log in
# build-fuzz/fuzz/run/TARGET.log. docs/fuzz_report.md has more.
# Usage: scripts/fuzz.sh [seconds-per-target]   (default 60)
#        COATFFT_FUZZ_BUILD_DIR (default build-fuzz), COATFFT_FUZZ_TARGETS (default all four)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build_dir=${COATFFT_FUZZ_BUILD_DIR:-build-fuzz}
read -r -a targets <<<"${COATFFT_FUZZ_TARGETS:-fuzz_scene fuzz_npy fuzz_csv fuzz_topography}"

if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
  exit 2
fi
# Only the library, the CLI's readers and the targets: no tests, benchmarks or tables, and no
# distributed layer (no reader is distributed yet); the libraries as unity builds (built once).
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DCOATFFT_FUZZ=ON -DCOATFFT_UNITY=ON -DCOATFFT_BUILD_TESTS=OFF \
  -DCOATFFT_MPI=OFF \
  -DCOATFFT_BUILD_BENCH=OFF -DCOATFFT_BUILD_TABLES=OFF -DCOATFFT_BUILD_EXAMPLES=OFF >/dev/null

# The value of `stat::NAME: VALUE` (libFuzzer's -print_final_stats) in a log, or "?".
fuzz_stat() { sed -n "s/^stat::$1: *//p" "$2" | tail -n 1 | grep . || echo "?"; }
# "cov: C ft: F corp: N" of libFuzzer's INITED or DONE line, or "?".
coverage() {
  grep -E "^#[0-9]+[[:space:]]+$1[[:space:]]" "$2" | tail -n 1 | sed -E 's/.*cov: ([0-9]+).*/\1/' | grep . || echo "?"
}

work="$(cd "$build_dir" && pwd)/fuzz/run"
status=0

# fuzz TARGET: SECONDS of libFuzzer on a fresh copy of its seed corpus; its summary line into
# $work/TARGET.line, and a non-zero exit on a finding.
fuzz() {
  local target=$1 corpus="$work/corpus/$1" findings="$work/findings/$1" log="$work/$1.log"
  local dict=() start=$SECONDS result="ok" found=0
  [ -f "fuzz/dict/$target.dict" ] && dict=(-dict="fuzz/dict/$target.dict")
  # TMPDIR: the targets' scratch folders stay inside the build folder, even after a crash.
  if ! TMPDIR="$work/tmp/$target" "$build_dir/fuzz/$target" -max_total_time="$seconds" \
    -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 -artifact_prefix="$findings/" \
    "${dict[@]}" "$corpus" >"$log" 2>&1; then
    result="FINDING: see $log and $findings/"
    found=1
  fi
  echo "$target: $result; $(fuzz_stat number_of_executed_units "$log") runs" \
    "in $((SECONDS - start)) s," \
    "coverage $(coverage INITED "$log") -> $(coverage DONE "$log") edges," \
    "$(fuzz_stat new_units_added "$log") new inputs, corpus $(ls "$corpus" | wc -l) files," \
    "peak RSS $(fuzz_stat peak_rss_mb "$log") MB" >"$work/$target.line"
  return $found
}

# Each target is built on its own, so that one that does not build leaves the others running.
built=()
for target in "${targets[@]}"; do
  rm -rf "$work/corpus/$target" "$work/findings/$target" "$work/tmp/$target" "$work/$target.line"
  mkdir -p "$work/corpus/$target" "$work/findings/$target" "$work/tmp/$target"
  cp fuzz/corpus/"$target"/* "$work/corpus/$target"/
  if cmake --build "$build_dir" -j "$(nproc)" --target "$target" >"$work/$target.build.log" 2>&1
  then
    built+=("$target")
  else
    echo "$target: BUILD FAILED, see $work/$target.build.log"
    status=1
  fi
done
# The targets fuzz side by side, one a core (each libFuzzer run is one process on one thread):
# every target still gets its SECONDS.
running=0
for target in "${built[@]}"; do
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz "$target" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
for target in "${built[@]}"; do cat "$work/$target.line"; done
exit $status
