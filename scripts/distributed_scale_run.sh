#!/usr/bin/env bash
# The distributed periodic operator and contact solve against the serial ones, as docs/scale.md
# reports them: for each grid, bench_distributed --serial, then under mpirun at each rank count
# (one process per row, so each row's peak memory is its own). Writes
# bench/results/distributed_operator.csv and (WHAT=contact or both) distributed_contact.csv; with
# WHAT=free, the free surface's DC-FFT on steel against the serial DcfftOperator,
# bench/results/distributed_dcfft.csv; with WHAT=split, the free surface of the coated body by
# frf-split against DcfftOperator(split_frf_kernel), bench/results/distributed_split.csv; with
# WHAT=output, a field's .npy file by MPI-IO against its NetCDF file by PnetCDF
# (bench_distributed_output), bench/results/distributed_output.csv.
#   Body: TiN 5 um on steel, period 1 mm; one FFTW thread a rank; FFTW_ESTIMATE plans. NESTED=1:
#   the contact with the nested start, serial and distributed (a last column: the coarse grids'
#   applications).
# Usage: scripts/distributed_scale_run.sh [N ...]   (default 2048 4096; RANKS, default "1 2 4";
#        WHAT: operator, contact or both (default), free, split or output; SERIAL=0 leaves out the serial rows; TAG
#        names other result files, distributed_operatorTAG.csv and distributed_contactTAG.csv;
#        BUILD_DIR, default build). As root, Open MPI's permission variables are set here.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(2048 4096)
read -r -a ranks <<<"${RANKS:-1 2 4}"
what=${WHAT:-both}
serial=${SERIAL:-1}
tag=${TAG:-}
nested=${NESTED:-0}
cmake --build "$build" --target bench_distributed >/dev/null
bench=$build/bench/bench_distributed
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
header() {
  echo "# benchmark = scripts/distributed_scale_run.sh ($1)"
  echo "# date = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "# cpu = $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "# hardware_threads = $(nproc); memory = $(free -g | awk '/Mem:/{print $2}') GiB"
  echo "# mpi = $(mpirun --version | head -n 1); ranks on one machine (shared memory)"
  echo "# body = ${2:-TiN 5 um on steel, period 1 mm}; one FFTW thread a rank; FFTW_ESTIMATE"
}
# One CSV: its header lines, then a row per size and rank count (bench_distributed FLAGS).
measure() {
  local results=$1
  shift
  for n in "${sizes[@]}"; do
    if [ "$serial" != 0 ]; then
      echo "== $n^2 serial $*" >&2
      "$bench" --serial --size "$n" "$@" >>"$tmp"
    fi
    for p in "${ranks[@]}"; do
      echo "== $n^2 np $p $*" >&2
      mpirun -np "$p" --oversubscribe "$bench" --size "$n" "$@" >>"$tmp"
    done
  done
  mv "$tmp" "$results"
  cat "$results"
}
if [ "$what" = free ]; then
{
  header "bench_distributed --free: the distributed DC-FFT of the free surface against DcfftOperator" \
    "steel, a free surface of 1 mm x 1 mm"
  echo "# apply_ms: median of 5 applications, each timed from a barrier to the slowest rank;"
  echo "#   transpose_ms: the transposes' share of one (communication and waits); rss_*: peak"
  echo "#   resident memory [MiB] before the operator (max over ranks), after (max, sum over ranks)"
  echo "N,ranks,threads,setup_s,apply_ms,transpose_ms,communication_share,rss_before_mb,rss_max_mb,rss_sum_mb"
} >"$tmp"
measure "$root/bench/results/distributed_dcfft$tag.csv" --free
trap - EXIT
exit 0
fi
if [ "$what" = output ]; then
  cmake --build "$build" --target bench_distributed_output >/dev/null
  bench=$build/bench/bench_distributed_output
  {
    header "bench_distributed_output: a field written as .npy by MPI-IO and as NetCDF by PnetCDF" \
      "none; the field written: a rough surface, H 0.8, rms slope 0.05, seed 2004, 1 mm x 1 mm"
    echo "# npy_s, netcdf_s: median of 5 writes (create, write, close; not synced to the disk), each"
    echo "#   timed from a barrier to the slowest rank; file_mib: the field's 8 N^2 bytes; folder: $(df --output=fstype "${TMPDIR:-/tmp}" | tail -1) ${TMPDIR:-/tmp}"
    echo "N,ranks,file_mib,npy_s,netcdf_s,netcdf_over_npy"
  } >"$tmp"
  measure "$root/bench/results/distributed_output$tag.csv"
  trap - EXIT
  exit 0
fi
if [ "$what" = split ]; then
{
  header "bench_distributed --free-split: the coated body's free surface by frf-split against DcfftOperator(split_frf_kernel)" \
    "TiN 5 um on steel, a free surface of 1 mm x 1 mm"
  echo "# setup_s: the coefficients (the split kernel: its quarter's rows, its lattice over the ranks)"
  echo "#   and their spectrum, the slowest rank; apply_ms: median of 5 applications, each timed from"
  echo "#   a barrier to the slowest rank; transpose_ms: the transposes' share of one; rss_*: peak"
  echo "#   resident memory [MiB] before the operator (max over ranks), after (max, sum over ranks)"
  echo "N,ranks,threads,setup_s,apply_ms,transpose_ms,communication_share,rss_before_mb,rss_max_mb,rss_sum_mb"
} >"$tmp"
measure "$root/bench/results/distributed_split$tag.csv" --free-split
trap - EXIT
exit 0
fi
if [ "$what" != contact ]; then
{
  header "bench_distributed: the distributed periodic operator"
  echo "# apply_ms: median of 5 applications, each timed from a barrier to the slowest rank;"
  echo "#   transpose_ms: the transposes' share of one (communication and waits); rss_*: peak"
  echo "#   resident memory [MiB] before the operator (max over ranks), after (max, sum over ranks)"
  echo "N,ranks,threads,setup_s,apply_ms,transpose_ms,communication_share,rss_before_mb,rss_max_mb,rss_sum_mb"
} >"$tmp"
measure "$root/bench/results/distributed_operator$tag.csv"
fi
if [ "$what" != operator ]; then
{
  header "bench_distributed --contact: a periodic rough contact solved on distributed fields"
  echo "# surface: H 0.8, rms slope 0.05, shortest wavelength 16 cells, roll-off 0.25 mm, seed 2004;"
  columns=N,ranks,threads,setup_s,iterations,applications,converged,area_fraction,solve_s,transpose_s,transpose_share,rss_max_mb,rss_sum_mb
  flags=(--contact)
  if [ "$nested" != 0 ]; then
    echo "#   mean pressure 0.045 E* x rms slope; tolerance 1e-10; the nested start (serial and distributed)"
    columns=$columns,coarse_applications
    flags+=(--nested)
  else
    echo "#   mean pressure 0.045 E* x rms slope; tolerance 1e-10; no nested start (serial and distributed)"
  fi
  echo "# solve_s: the solve on the slowest rank; transpose_s: the operator's transposes within it"
  echo "#   (the preconditioner's are not counted); rss_*: peak resident memory [MiB] of a rank, sum"
  echo "$columns"
} >"$tmp"
measure "$root/bench/results/distributed_contact$tag.csv" "${flags[@]}"
fi
trap - EXIT
