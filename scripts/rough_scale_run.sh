#!/usr/bin/env bash
# A periodic rough contact of a coated body at large grids, through the command line as a user runs
# it: `coatfft surface` makes the topography, Debian's python3 turns it into the gap (h = max z - z,
# docs/surfaces.md), `coatfft run` solves the contact, and bench_peak_rss records its wall time and
# peak resident memory. Writes bench/results/rough_scale.csv (docs/benchmarks.md, "Rough contact
# at scale").
#   Body: TiN 5 um on steel; period 1 mm; H = 0.8, rms slope 0.05, shortest wavelength 16 cells,
#   roll-off at 0.25 mm, seed 2004; load p_m/(E*_steel g) = 0.045 (about 10 % contact area);
#   frf-split, [contact] tolerance 1e-10, two threads; only summary.json and pressure.npy written.
# Usage: scripts/rough_scale_run.sh [N ...]   (default 4096 8192; BUILD_DIR, default build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(4096 8192)
python=/usr/bin/python3
cmake --build "$build" --target coatfft_exe bench_peak_rss >/dev/null
coatfft=$build/coatfft
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$root/bench/results/rough_scale.csv
{
  echo "# benchmark = scripts/rough_scale_run.sh (coatfft run, periodic rough contact, coated body)"
  echo "# date = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "# cpu = $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "# hardware_threads = $(nproc); memory = $(free -g | awk '/Mem:/{print $2}') GiB"
  echo "# body = TiN 5 um (E 400 GPa, nu 0.25) on steel; period 1 mm; H 0.8, rms slope 0.05,"
  echo "#   shortest wavelength 16 cells, roll-off 0.25 mm, seed 2004; p_m/(E* g) = 0.045"
  echo "# wall_s and peak_rss_mb: the whole coatfft run (bench_peak_rss); setup_seconds and"
  echo "#   solve_seconds from summary.json"
  echo "N,iterations,operator_applications,converged,area_fraction,max_pressure_pa,setup_seconds,solve_seconds,wall_s,peak_rss_mb"
} >"$tmp/rows.csv"
load=$($python -c "print(0.045 * 210e9 / (1 - 0.3**2) * 0.05 * 1e-3 * 1e-3)")
for n in "${sizes[@]}"; do
  echo "== $n^2" >&2
  "$coatfft" surface -o "$tmp/z.npy" --overwrite --nx "$n" --ny "$n" --lx 1e-3 --ly 1e-3 --hurst 0.8 \
    --rms-slope 0.05 --short-cutoff "$($python -c "print(16 * 1e-3 / $n)")" --long-cutoff 2.5e-4 \
    --seed 2004
  $python -c "
import numpy as np
z = np.load('$tmp/z.npy')
np.save('$tmp/gap.npy', z.max() - z)"
  rm "$tmp/z.npy"
  cat >"$tmp/scene.toml" <<TOML
[grid]
nx = $n
ny = $n
lx = 1e-3
ly = 1e-3
boundary = "periodic"
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 5e-6
[method]
name = "frf-split"
threads = 2
[contact]
indenter = "height_map"
path = "$tmp/gap.npy"
load = $load
[output]
fields = ["summary", "pressure"]
TOML
  rm -rf "$tmp/out"
  "$build/bench/bench_peak_rss" "$coatfft" run "$tmp/scene.toml" -o "$tmp/out" >"$tmp/rss.txt"
  cat "$tmp/rss.txt" >&2
  $python - "$n" "$tmp/out/summary.json" "$tmp/rss.txt" >>"$tmp/rows.csv" <<'PY'
import json, sys
n, summary, rss = sys.argv[1], json.load(open(sys.argv[2])), dict(
    line.split(" = ") for line in open(sys.argv[3]).read().split("\n") if " = " in line)
area = summary["contact_area"] / 1e-6
print(f"{n},{summary['iterations']},{summary['operator_applications']},"
      f"{int(summary['converged'])},{area:.4f},{summary['max_pressure']:.4g},"
      f"{summary['setup_seconds']:.3g},{summary['solve_seconds']:.4g},"
      f"{float(rss['wall_s']):.4g},{float(rss['peak_rss_mb']):.0f}")
PY
  rm -f "$tmp/gap.npy"
done
mv "$tmp/rows.csv" "$results"
cat "$results"
