#!/usr/bin/env bash
# Builds coatfft (Release) and regenerates the speed-against-error results (issue 5):
#   bench/results/sweep.csv, bench/results/pareto_<case>.png, bench/results/seed_figures/*.csv,
#   bench/results/sweep_reference_check.csv, bench/results/coatfft_run_rss.txt,
#   docs/figures/seed_fig{2,3}_*.png and the generated block of docs/benchmarks_sweep.md.
#
# Usage: scripts/run_benchmarks.sh [--full | --quick | --tiny]   (default --full, ~10 min on 2 cores)
# Environment: BUILD_DIR (default build-release), JOBS (default 2), SWEEP_ARGS (extra bench_sweep
# options, e.g. "--threads 2" or "--planning measure").
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build-release}
mode=${1:---full}
case "$mode" in --full | --quick | --tiny) ;; *) echo "usage: $0 [--full|--quick|--tiny]" >&2; exit 2 ;; esac
results=$root/bench/results
python=/usr/bin/python3

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOATFFT_BUILD_BENCH=ON \
  -DCOATFFT_BUILD_CLI=ON >/dev/null
cmake --build "$build" -j "${JOBS:-2}" --target bench_sweep coatfft_exe
sweep=$build/bench/bench_sweep
mkdir -p "$results"

echo "== sweep ($mode)"
# A failed row is reported in the CSV ("# failed: ...") and by the exit status; keep going so that
# the plots and tables show what did run.
"$sweep" "$mode" --output "$results/sweep.csv" ${SWEEP_ARGS:-} || echo "warning: some rows failed" >&2

echo "== reference check"
"$sweep" --check-reference --output "$results/sweep_reference_check.csv"

echo "== seed figure data"
figure_mode=""
[ "$mode" = "--tiny" ] && figure_mode="--tiny"
"$sweep" --figures "$results/seed_figures" $figure_mode

echo "== peak RSS of a whole coatfft run (2048^2 DC-FFT Hertz scene)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/hertz_2048.toml" <<'EOF'
[grid]
nx = 2048
ny = 2048
lx = 3.0e-3
ly = 3.0e-3
[substrate]
material = "steel"
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 1.0e-3
[method]
name = "dcfft"
EOF
{
  echo "scene: Hertz p0 = 1 GPa, a = 1 mm, steel, 2048 x 2048 cells on [-1.5a, 1.5a]^2, dcfft"
  echo "command: coatfft run hertz_2048.toml -o out/   (writes pressure.npy, uz.npy, displacement.csv, summary.json)"
  echo "bench_sweep --peak-rss (fork/exec + wait4 rusage):"
  "$sweep" --peak-rss "$build/coatfft" run "$tmp/hertz_2048.toml" -o "$tmp/out1" | sed 's/^/  /'
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -v "$build/coatfft" run "$tmp/hertz_2048.toml" -o "$tmp/out2" 2>"$tmp/time.txt" >/dev/null
    echo "/usr/bin/time -v:"
    grep -E "Maximum resident set size|Elapsed \(wall clock\)" "$tmp/time.txt" | sed 's/^\s*/  /'
  fi
} | tee "$results/coatfft_run_rss.txt"

echo "== plots and tables"
"$python" "$root/scripts/plot_pareto.py" "$results/sweep.csv" --outdir "$results" \
  --markdown "$root/docs/benchmarks_sweep.md" \
  --reference-check "$results/sweep_reference_check.csv" --rss "$results/coatfft_run_rss.txt"
"$python" "$root/scripts/plot_seed_figures.py" "$results/seed_figures" --outdir "$root/docs/figures"
echo "done"
