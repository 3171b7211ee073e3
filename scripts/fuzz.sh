#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) in build-fuzz and runs each for
# SECONDS seconds on a copy of its seed corpus (fuzz/corpus/TARGET), so the repository is left as
# it is. Prints one line per target and exits non-zero if any target found a crash, a sanitizer
# report or an exception other than InvalidArgument; its input is kept under
# build-fuzz/fuzz/run/findings/TARGET/, the log in build-fuzz/fuzz/run/TARGET.log. docs/fuzz_report.md has more.
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
for target in "${targets[@]}"; do
  corpus="$work/corpus/$target"
  findings="$work/findings/$target"
  log="$work/$target.log"
  rm -rf "$corpus" "$findings" "$work/tmp/$target"
  mkdir -p "$corpus" "$findings" "$work/tmp/$target"
  cp fuzz/corpus/"$target"/* "$corpus"/
  dict=()
  [ -f "fuzz/dict/$target.dict" ] && dict=(-dict="fuzz/dict/$target.dict")
  # Each target is built on its own, so that one that does not build leaves the others running.
  if ! cmake --build "$build_dir" -j "$(nproc)" --target "$target" >"$work/$target.build.log" 2>&1
  then
    echo "$target: BUILD FAILED, see $work/$target.build.log"
    status=1
    continue
  fi
  start=$SECONDS
  # TMPDIR: the targets' scratch folders stay inside the build folder, even after a crash.
  if TMPDIR="$work/tmp/$target" "$build_dir/fuzz/$target" -max_total_time="$seconds" \
    -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 -artifact_prefix="$findings/" \
    "${dict[@]}" "$corpus" >"$log" 2>&1; then
    result="ok"
  else
    result="FINDING: see $log and $findings/"
    status=1
  fi
  echo "$target: $result; $(fuzz_stat number_of_executed_units "$log") runs" \
    "in $((SECONDS - start)) s," \
    "coverage $(coverage INITED "$log") -> $(coverage DONE "$log") edges," \
    "$(fuzz_stat new_units_added "$log") new inputs, corpus $(ls "$corpus" | wc -l) files," \
    "peak RSS $(fuzz_stat peak_rss_mb "$log") MB"
done
exit $status
