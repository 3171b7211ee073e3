#!/usr/bin/env bash
# Builds coatfft (Release, with the validation table programs of tables/) and regenerates the
# generated tables of docs/validation.md and docs/validation/, all of them or those named:
#   hertz_dcfft     docs/validation/hertz_dcfft.md and docs/validation.md's generated block
#                   hertz_dcfft (hertz_dcfft_table: DC-FFT vs Hertz)
#   contact         docs/validation/contact.md          contact_table        (contact solver vs Hertz/punch)
#   frf_pipelines   docs/validation/frf_pipelines.md    frf_pipelines_table  (Spinu 2021's FRF pipelines and g(0))
#   split_kernel    docs/validation/split_kernel.md     split_kernel_table   (frf-split vs Hankel reference)
#   hard_cases      docs/validation/hard_cases.md       hard_cases_table     (every FRF method on the hard bodies)
#   pipeline_error  docs/validation/pipeline_error.md   pipeline_error_table (error model of the FRF pipelines)
#   stress          docs/validation/stress.md           stress_table         (stresses at depth vs Johnson, Hamilton, Hankel)
#   traction        docs/validation/traction.md         traction_table       (surface displacements under tangential tractions; sliding)
#   partial_slip    docs/validation/partial_slip.md     partial_slip_table   (partial slip vs Cattaneo-Mindlin; fretting; coated steel)
#   hardness        docs/validation/hardness.md         hardness_table       (the hardness cap: sphere limits; rough plastic area)
#   adhesion        docs/validation/adhesion.md         adhesion_table       (adhesion vs Maugis-Dugdale; thick and thin films; rough pull-off)
#   rough_contact   docs/validation/rough_contact.md    rough_contact_table  (rough periodic contact: area against load, kappa;
#                   and its plot docs/figures/rough_contact_area.png, scripts/plot_rough_contact.py)
#   coated          docs/validation.md's generated block coated_convergence, from the existing
#                   bench/results/sweep.csv (no program is run: scripts/run_benchmarks.sh runs the
#                   sweep and regenerates this block too)
# Each program's --check (run by ctest as table_<name>_check) recomputes a subset of its table
# and compares it with the reference; this script writes the full tables.
# Usage: scripts/make_validation_docs.sh [TABLE...]   Environment: BUILD_DIR (default build-release)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build-release}
python=/usr/bin/python3
tables=("$@")
[ ${#tables[@]} -eq 0 ] && tables=(hertz_dcfft contact frf_pipelines split_kernel hard_cases pipeline_error stress traction partial_slip hardness adhesion rough_contact coated)
programs=()
for t in "${tables[@]}"; do
  case "$t" in
    hertz_dcfft | contact | frf_pipelines | split_kernel | hard_cases | pipeline_error | stress | traction | partial_slip | hardness | adhesion | rough_contact) programs+=("${t}_table") ;;
    coated) ;;
    *) echo "usage: $0 [hertz_dcfft|contact|frf_pipelines|split_kernel|hard_cases|pipeline_error|stress|traction|partial_slip|hardness|adhesion|rough_contact|coated ...]" >&2; exit 2 ;;
  esac
done
if [ ${#programs[@]} -gt 0 ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOATFFT_BUILD_TABLES=ON >/dev/null
  cmake --build "$build" -j "${JOBS:-2}" --target "${programs[@]}"
fi
cd "$root"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for t in "${tables[@]}"; do
  case "$t" in
    hertz_dcfft)
      "$build/tables/hertz_dcfft_table" docs/validation/hertz_dcfft.md --csv "$tmp/hertz_dcfft.csv"
      "$python" scripts/markdown_blocks.py docs/validation.md hertz_dcfft "$tmp/hertz_dcfft.csv" ;;
    coated)
      "$python" scripts/markdown_blocks.py docs/validation.md coated_convergence \
        bench/results/sweep.csv --view coated-convergence ;;
    rough_contact)
      "$build/tables/rough_contact_table" docs/validation/rough_contact.md
      "$python" scripts/plot_rough_contact.py docs/validation/rough_contact.md \
        docs/figures/rough_contact_area.png ;;
    *) "$build/tables/${t}_table" "docs/validation/$t.md" ;;
  esac
done
echo "regenerated: ${tables[*]}"
