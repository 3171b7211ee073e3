#!/usr/bin/env bash
# The Python module as pip installs it (docs/python.md, "Installing"): `pip install
# --no-build-isolation` with Debian's packages only (setuptools drives the project's CMake), from a
# copy of the source tree (setuptools writes its build and egg-info folders into the tree it
# builds), into a temporary prefix; then the installed module computes the Hertz displacement on
# steel from another directory and compares it with the closed form.
# Usage: package_check.sh   (Debian's /usr/bin/python3; needs python3-pip, -setuptools, -wheel)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

tar -C "$root" --exclude='./build*' --exclude='./out*' --exclude='__pycache__' -cf - . |
  (mkdir "$work/source" && tar -C "$work/source" -xf -)
# --prefix also lifts Debian 12's externally-managed-environment guard (PEP 668), which concerns
# the system's own site-packages only.
/usr/bin/python3 -m pip install --no-build-isolation --no-deps --no-index --quiet \
  --root-user-action=ignore \
  --prefix "$work/prefix" "$work/source"
init=$(find "$work/prefix" -path '*/coatfft/__init__.py' | head -n 1)
test -n "$init" || { echo "FAIL: pip installed no coatfft package" >&2; exit 1; }
site=$(dirname "$(dirname "$init")")

cd "$work"
PYTHONPATH="$site" PYTHONNOUSERSITE=1 /usr/bin/python3 - "$site" <<'PY'
import sys
import numpy as np
import coatfft

assert coatfft.__file__.startswith(sys.argv[1]), f"imported {coatfft.__file__}, not the install"
grid = coatfft.Grid(64, 64, 4e-3, 4e-3)
steel = coatfft.material("steel")
u = coatfft.make_operator(grid, steel).apply(coatfft.hertz_pressure(grid, 1e9, 1e-3))
x, y = np.meshgrid(grid.x, grid.y)
reference = coatfft.hertz_displacement(np.hypot(x, y), 1e9, 1e-3, steel.E_star)
error = np.abs(u - reference).max() / reference.max()
# Centre sampling of a Hertz load 16 cells in radius: 2.5e-3 of u(0) (docs/validation.md).
assert error < 5e-3, f"Hertz error {error}"
print(f"pip-installed coatfft {coatfft.__version__} from {coatfft.__file__}: Hertz error {error:.3g}")
PY
