#!/bin/sh
# Writes tabulated_frf.csv, the [frf] table of tabulated_frf.toml: coatfft's own FRF of that
# scene's [substrate] and [[coating]] (h = 0.1 mm) at 80 points per decade over k h = 1e-8 to
# 1e3, where the cubic spline of TabulatedFrf interpolates it to < 2e-7 (docs/frf.md), converted
# from the columns of `coatfft frf` to the k,H table of [frf].
# Usage: make_tabulated_frf.sh [PATH_TO_COATFFT]
set -eu
coatfft=${1:-coatfft}
here=$(dirname "$0")
"$coatfft" frf "$here/tabulated_frf.toml" --k-min 1e-4 --k-max 1e7 --points 881 |
  awk -F, 'NR == 1 { print "k,H"; next } { print $1 "," $3 }' >"$here/tabulated_frf.csv"
