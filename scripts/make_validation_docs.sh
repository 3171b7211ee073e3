#!/usr/bin/env bash
# Builds coatfft (Release, with the validation programs) and regenerates every generated table of
# docs/validation.md:
#   docs/validation_hertz_dcfft.md      hertz_dcfft_table     (DC-FFT vs Hertz, issue 2)
#   docs/validation_contact.md          contact_table         (contact solver vs Hertz/punch, issue 4)
#   docs/validation_seed_pipelines.md   seed_pipelines_table  (seed's FRF pipelines and g(0), issue 6)
#   docs/validation_split_kernel.md     split_kernel_table    (frf-split vs Hankel reference, issue 6)
# Usage: scripts/make_validation_docs.sh      Environment: BUILD_DIR (default build-release)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build-release}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOATFFT_BUILD_BENCH=ON >/dev/null
programs=(hertz_dcfft_table contact_table seed_pipelines_table split_kernel_table)
cmake --build "$build" -j "${JOBS:-2}" --target "${programs[@]}"
cd "$root"
"$build/validation/hertz_dcfft_table" docs/validation_hertz_dcfft.md
"$build/validation/contact_table" docs/validation_contact.md
"$build/validation/seed_pipelines_table" docs/validation_seed_pipelines.md
"$build/validation/split_kernel_table" docs/validation_split_kernel.md
echo "regenerated docs/validation_*.md"
