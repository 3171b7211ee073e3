#!/usr/bin/env bash
# The distributed periodic operator against the serial one, as docs/scale.md reports it: for each
# grid, bench_distributed --serial, then under mpirun at each rank count (one process per row, so
# each row's peak memory is its own). Writes bench/results/distributed_operator.csv.
#   Body: TiN 5 um on steel, period 1 mm; one FFTW thread a rank; FFTW_ESTIMATE plans.
# Usage: scripts/distributed_scale_run.sh [N ...]   (default 2048 4096; RANKS, default "1 2 4";
#        BUILD_DIR, default build). As root, Open MPI's permission variables are set here.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(2048 4096)
read -r -a ranks <<<"${RANKS:-1 2 4}"
cmake --build "$build" --target bench_distributed >/dev/null
bench=$build/bench/bench_distributed
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
results=$root/bench/results/distributed_operator.csv
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
{
  echo "# benchmark = scripts/distributed_scale_run.sh (bench_distributed: the distributed periodic operator)"
  echo "# date = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "# cpu = $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "# hardware_threads = $(nproc); memory = $(free -g | awk '/Mem:/{print $2}') GiB"
  echo "# mpi = $(mpirun --version | head -n 1); ranks on one machine (shared memory)"
  echo "# body = TiN 5 um on steel, period 1 mm; one FFTW thread a rank; FFTW_ESTIMATE"
  echo "# apply_ms: median of 5 applications, each timed from a barrier to the slowest rank;"
  echo "#   transpose_ms: the transposes' share of one (communication and waits); rss_*: peak"
  echo "#   resident memory [MiB] before the operator (max over ranks), after (max, sum over ranks)"
  echo "N,ranks,threads,setup_s,apply_ms,transpose_ms,communication_share,rss_before_mb,rss_max_mb,rss_sum_mb"
} >"$tmp"
for n in "${sizes[@]}"; do
  echo "== $n^2 serial" >&2
  "$bench" --serial --size "$n" >>"$tmp"
  for p in "${ranks[@]}"; do
    echo "== $n^2 np $p" >&2
    mpirun -np "$p" --oversubscribe "$bench" --size "$n" >>"$tmp"
  done
done
mv "$tmp" "$results"
trap - EXIT
cat "$results"
