#!/usr/bin/env bash
# Builds coatfft (Release) and regenerates the benchmark results and the generated blocks of
# docs/benchmarks.md (docs/benchmarks.md, "Regenerate everything"):
#   speed against error: bench/results/sweep.csv, bench/results/pareto_<case>.png,
#   bench/results/spinu_figures/*.csv, bench/results/sweep_reference_check.csv,
#   bench/results/coatfft_run_rss.txt, docs/figures/spinu_fig{2,3}_*.png, and (not with --tiny,
#   whose sweep has no coated case) docs/validation.md's block coated_convergence;
#   with --full also bench/results/dcfft.csv, fft_sizes.csv, setup.csv, setup_2048.csv,
#   setup_alpha4.csv, frf_eval.csv, contact.csv, rough_contact.csv, precision.csv and their blocks
#   in docs/benchmarks.md
#   (dcfft_direct: direct summation against DC-FFT), and auto_tolerance.csv (docs/auto.md,
#   section 5: the automatic method choice against hand-picked settings).
# Programs (bench/, one per file; each takes --help): bench_sweep (with its child bench_sweep_row),
# bench_reference_check, bench_figures, bench_peak_rss, and with --full bench_dcfft,
# bench_fft_sizes, bench_setup, bench_frf, bench_contact, bench_rough_contact, bench_precision,
# bench_auto_tolerance, bench_stress. The rough contact at 4096^2 and 8192^2 (tens of minutes) is
# scripts/rough_scale_run.sh, run on its own.
#
# Usage: scripts/run_benchmarks.sh [--full | --quick | --tiny]   (default --full, ~10 min on 2 cores;
#        --quick and --tiny run the sweep only)
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
targets="bench_sweep bench_sweep_row bench_reference_check bench_figures bench_peak_rss coatfft_exe"
[ "$mode" = "--full" ] && targets="$targets bench_dcfft bench_fft_sizes bench_setup bench_frf bench_contact"
[ "$mode" = "--full" ] && targets="$targets bench_auto_tolerance bench_stress bench_rough_contact"
[ "$mode" = "--full" ] && targets="$targets bench_precision"
# shellcheck disable=SC2086
cmake --build "$build" -j "${JOBS:-2}" --target $targets
bench=$build/bench
sweep=$bench/bench_sweep
mkdir -p "$results"

echo "== sweep ($mode)"
# A failed row is reported in the CSV ("# failed: ...") and by the exit status; keep going so that
# the plots and tables show what did run.
"$sweep" "$mode" --output "$results/sweep.csv" ${SWEEP_ARGS:-} || echo "warning: some rows failed" >&2

echo "== reference check"
"$bench/bench_reference_check" --output "$results/sweep_reference_check.csv"

echo "== data of the figures of Spinu (2021)"
figure_mode=""
[ "$mode" = "--tiny" ] && figure_mode="--tiny"
"$bench/bench_figures" "$results/spinu_figures" $figure_mode

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
  echo "bench_peak_rss (fork/exec + wait4 rusage):"
  "$bench/bench_peak_rss" "$build/coatfft" run "$tmp/hertz_2048.toml" -o "$tmp/out1" | sed 's/^/  /'
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -v "$build/coatfft" run "$tmp/hertz_2048.toml" -o "$tmp/out2" 2>"$tmp/time.txt" >/dev/null
    echo "/usr/bin/time -v:"
    grep -E "Maximum resident set size|Elapsed \(wall clock\)" "$tmp/time.txt" | sed 's/^\s*/  /'
  fi
} | tee "$results/coatfft_run_rss.txt"

echo "== plots and tables"
"$python" "$root/scripts/plot_pareto.py" "$results/sweep.csv" --outdir "$results" \
  --markdown "$root/docs/benchmarks.md" \
  --reference-check "$results/sweep_reference_check.csv" --rss "$results/coatfft_run_rss.txt"
"$python" "$root/scripts/plot_spinu_figures.py" "$results/spinu_figures" --outdir "$root/docs/figures"
blocks="$root/scripts/markdown_blocks.py"
if [ "$mode" != "--tiny" ]; then
  "$python" "$blocks" "$root/docs/validation.md" coated_convergence "$results/sweep.csv" \
    --view coated-convergence
fi

if [ "$mode" = "--full" ]; then
  echo "== DC-FFT against the bare padded FFTW pipeline"
  "$bench/bench_dcfft" "$results/dcfft.csv"
  echo "== DC-FFT on awkward sizes (fast FFT padding)"
  "$bench/bench_fft_sizes" "$results/fft_sizes.csv"
  echo "== setup against application"
  "$bench/bench_setup" "$results/setup.csv" --sizes 512,1024 --threads 1,2 --reps 5
  "$bench/bench_setup" "$results/setup_2048.csv" --sizes 2048 --threads 1,2 --reps 3
  "$bench/bench_setup" "$results/setup_alpha4.csv" --sizes 1024 --threads 1 --reps 5 --alpha 4
  echo "== FRF evaluation"
  "$bench/bench_frf" "$results/frf_eval.csv"
  echo "== contact solver"
  "$bench/bench_contact" "$results/contact.csv"
  echo "== contact solver on periodic rough surfaces"
  "$bench/bench_rough_contact" "$results/rough_contact.csv"
  echo "== single against double precision"
  "$bench/bench_precision" "$results/precision.csv"
  echo "== automatic method choice per tolerance, against hand-picked settings"
  "$bench/bench_auto_tolerance" "$results/auto_tolerance.csv"
  echo "bench_stress:"
  "$bench/bench_stress" "$results/stress.csv"
  doc=$root/docs/benchmarks.md
  "$python" "$blocks" "$doc" dcfft "$results/dcfft.csv"
  "$python" "$blocks" "$doc" dcfft_direct "$results/dcfft.csv" --view direct-speedup
  "$python" "$blocks" "$doc" fft_sizes "$results/fft_sizes.csv"
  "$python" "$blocks" "$doc" setup "$results/setup.csv"
  "$python" "$blocks" "$doc" setup_2048 "$results/setup_2048.csv"
  "$python" "$blocks" "$doc" frf_eval "$results/frf_eval.csv"
  "$python" "$blocks" "$doc" contact "$results/contact.csv" \
    --columns control,preconditioned,linearity,N,iterations,converged,solve_ms,applies,solve_over_apply,a_error,p0_error
  "$python" "$blocks" "$doc" rough_contact "$results/rough_contact.csv" \
    --columns N,body,linearity,precision,tolerance,iterations,applications,converged,area_fraction,pressure_error,apply_ms,solve_ms,solve_over_apply
  "$python" "$blocks" "$doc" precision "$results/precision.csv"
fi
echo "done"
