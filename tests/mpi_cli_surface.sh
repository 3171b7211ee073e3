#!/usr/bin/env bash
# `coatfft surface` under mpirun (docs/scale.md): at 1, 2 and 3 ranks (3: uneven slabs) the same
# .npy file as the serial command, byte for byte, over sizes whose rows split unevenly; a NetCDF
# file too (written by the ranks together), also where a rank holds no rows; a command that does not
# run distributed is refused on one line, writing nothing.
# Usage: mpi_cli_surface.sh COATFFT MPIEXEC
set -euo pipefail
coatfft=$1
mpiexec=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }
# Each mpirun costs about half a second: all rank counts on the first case, 3 on the other (the
# library's test checks both rms kinds at every rank count).
for case in "1 2 3: 64 50 --rms-slope 0.1" "3: 30 14 --rms-height 1e-6"; do
  read -r -a rank_counts <<<"${case%%:*}"
  read -r nx ny rms <<<"${case#*: }"
  args="--nx $nx --ny $ny --lx 1e-3 --ly 0.8e-3 --hurst 0.7 $rms --seed 2026"
  "$coatfft" surface -o "$tmp/serial.npy" $args --overwrite >/dev/null
  for ranks in "${rank_counts[@]}"; do
    "$mpiexec" -np "$ranks" --oversubscribe "$coatfft" surface -o "$tmp/np$ranks.npy" $args \
      --overwrite >"$tmp/out.txt"
    cmp -s "$tmp/serial.npy" "$tmp/np$ranks.npy" || fail "$nx x $ny $rms at $ranks ranks differs"
    # One line from rank 0 only.
    [ "$(wc -l <"$tmp/out.txt")" -eq 1 ] || fail "$(cat "$tmp/out.txt")"
  done
done
# NetCDF at 3 ranks: 14 rows split 5, 5, 4; 4 rows split 2, 2, 0.
for size in "30 14" "8 4"; do
  read -r nx ny <<<"$size"
  args="--nx $nx --ny $ny --lx 1e-3 --ly 0.8e-3 --hurst 0.7 --rms-height 1e-6 --seed 2026"
  "$coatfft" surface -o "$tmp/serial.nc" $args >/dev/null
  "$mpiexec" -np 3 --oversubscribe "$coatfft" surface -o "$tmp/np3.nc" $args >/dev/null
  cmp -s "$tmp/serial.nc" "$tmp/np3.nc" || fail "$nx x $ny NetCDF at 3 ranks differs"
  rm "$tmp/serial.nc" "$tmp/np3.nc"
done
# Refusals: exit status 2, one line on stderr naming the cause, no file.
refused() {
  local expect=$1
  shift
  if "$mpiexec" -np 2 --oversubscribe "$coatfft" "$@" >/dev/null 2>"$tmp/err.txt"; then
    fail "accepted: $*"
  fi
  grep -q "$expect" "$tmp/err.txt" || fail "no \"$expect\" in: $(cat "$tmp/err.txt")"
  [ "$(grep -c '^coatfft: error' "$tmp/err.txt")" -eq 1 ] || fail "not one line: $(cat "$tmp/err.txt")"
}
# A folder in the output's place is left as it is.
mkdir "$tmp/z.nc"
refused "z.nc" surface -o "$tmp/z.nc" --nx 8 --ny 8 --lx 1e-3 --ly 1e-3 --hurst 0.8 \
  --rms-height 1e-6
[ -d "$tmp/z.nc" ] && [ -z "$(ls -A "$tmp/z.nc")" ] || fail "z.nc changed"
refused "\`topography\` does not run distributed" topography "$tmp/none.npy" -o "$tmp/out.npy"
[ ! -e "$tmp/out.npy" ] || fail "out.npy written"
echo "mpi_cli_surface: all checks passed"
