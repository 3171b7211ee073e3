#!/usr/bin/python3
"""A body given by a frequency response function written in numpy (UserFrf), checked on the one
case with a closed form: the homogeneous half-space, H(k) = 2 / (E* k) (Boussinesq; Johnson
1985, section 3.2; docs/conventions.md).

The FRF is a Python function of a float64 array of wavenumbers k [rad/m] returning H [m/Pa],
with its limits c0 = lim k H at k -> 0 (2/E* of the substrate) and c_inf = lim k H at k -> inf
(2/E* of the top layer), here both 2/E* of steel. coatfft calls it with batches of wavenumbers
wherever it can (docs/python.md, "UserFrf batching"); the function here counts its calls and
their sizes, and the script prints them for each step.

1. validate_frf(frf, steel, grid): the checks of `coatfft validate-frf`: the limits, H at and
   between sample wavenumbers, the frf-split displacement of Hertz and uniform-disk loads
   against Love's DC-FFT, and the Hankel integrals of the FRF against those of steel. It must
   pass (tolerance 1e-6).
2. The frf-split operator of the UserFrf against Love's DC-FFT on the material itself
   (method="dcfft"), under a cell-averaged Hertz pressure (p0 = 1 GPa, a = 1 mm, 128 x 128 cells
   over [-1.5a, 1.5a]^2): max |u_frf - u_dcfft| / max |u_dcfft| must be below 1e-10, the floor of
   validate-frf's displacement checks (docs/scene_format.md, "Validating a table"; computed: a
   few 1e-16: frf-split's kernel is Love's coefficients for E* = 2/c_inf plus the kernels of
   two terms that vanish for this FRF, docs/split_kernel.md section 2).
3. The continuous displacement of the Hertz load through the FRF (hankel_displacement) against
   Johnson's closed form at r = 0, a/2, a, 2a: relative to u(0) below 1e-9, the floor of
   validate-frf's Hankel checks.

Run: /usr/bin/python3 examples/python/user_frf.py [--out DIR]
(with PYTHONPATH=build/python unless coatfft is installed). Writes user_frf.png (the
wavenumbers of each call of the function, step by step) into DIR, by default out/python/
under the current directory. Exit status 1 when a check fails.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import coatfft  # noqa: E402

P0 = 1e9  # Hertz peak pressure [Pa]
A = 1e-3  # load radius [m]


class HalfSpaceFrf:
    """H(k) = 2 / (E* k) for an array of k, recording the size of every batch and every k."""

    def __init__(self, material):
        self.E_star = material.E_star
        self.batches = []
        self.wavenumbers = []

    def __call__(self, k):
        self.batches.append(k.size)
        self.wavenumbers.append(k.copy())  # k belongs to coatfft: copy what is kept
        return 2.0 / (self.E_star * k)

    def take(self):
        """The batch sizes since the last take(), and forget them."""
        batches, self.batches = self.batches, []
        return batches


def describe(step, batches):
    ones = sum(1 for b in batches if b == 1)
    print(f"  {step}: {len(batches)} calls, {sum(batches)} wavenumbers "
          f"(largest batch {max(batches, default=0)}, {ones} of one wavenumber)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "python"),
                        help="folder for the figure (default: out/python)")
    args = parser.parse_args()

    steel = coatfft.material("steel")
    function = HalfSpaceFrf(steel)
    user = coatfft.UserFrf(function, c0=2 / steel.E_star, c_inf=2 / steel.E_star)
    grid = coatfft.Grid(128, 128, 3 * A, 3 * A)
    failures = []

    # 1. The checks of coatfft validate-frf.
    validation = coatfft.validate_frf(user, steel, grid)
    print(f"validate_frf: {'passed' if validation['passed'] else 'FAILED'} "
          f"(reference: {validation['reference']})")
    for check in validation["checks"]:
        print(f"  {check['name']:24s} {check['difference']:.2e} (tolerance "
              f"{check['tolerance']:.0e}) {'ok' if check['passed'] else 'FAILED'}")
    validation_batches = function.take()
    if not validation["passed"]:
        failures.append("validate_frf")

    # 2. frf-split of the UserFrf against Love's DC-FFT on steel.
    p = coatfft.hertz_pressure(grid, P0, A, sampling="cell_average")
    op_user = coatfft.make_operator(grid, user, method="frf-split")
    operator_batches = function.take()
    u_user = op_user.apply(p)
    u_love = coatfft.make_operator(grid, steel, method="dcfft").apply(p)
    difference = float(np.abs(u_user - u_love).max() / np.abs(u_love).max())
    print(f"frf-split of the UserFrf against dcfft on steel: max |du| / max |u| = "
          f"{difference:.2e} (bound 1e-10)")
    if not difference < 1e-10:
        failures.append(f"frf-split against dcfft: {difference:.2e}")

    # 3. The Hankel integral of the UserFrf against the closed form.
    r = np.array([0.0, 0.5, 1.0, 2.0]) * A
    u_hankel = coatfft.hankel_displacement(user, r, P0, A, load="hertz")
    hankel_batches = function.take()
    u_hertz = coatfft.hertz_displacement(r, P0, A, steel.E_star)
    hankel_error = float(np.abs(u_hankel - u_hertz).max() / u_hertz[0])
    print(f"Hankel integral of the UserFrf against Hertz at r/a = 0, 0.5, 1, 2: "
          f"{hankel_error:.2e} of u(0) (bound 1e-9)")
    if not hankel_error < 1e-9:
        failures.append(f"Hankel against Hertz: {hankel_error:.2e}")

    print(f"calls of the function (UserFrf.calls = {user.calls}):")
    describe("validate_frf", validation_batches)
    describe("make_operator(method=\"frf-split\")", operator_batches)
    describe("hankel_displacement at 4 radii", hankel_batches)

    os.makedirs(args.out, exist_ok=True)
    fig, axes = plt.subplots(figsize=(7.5, 4.2), constrained_layout=True)
    call = 0
    for step, batches in (("validate_frf", validation_batches),
                          ("make_operator, frf-split", operator_batches),
                          ("hankel_displacement", hankel_batches)):
        ks = function.wavenumbers[call:call + len(batches)]
        xs = np.concatenate([np.full(k.size, call + n + 1) for n, k in enumerate(ks)])
        axes.semilogy(xs, np.concatenate(ks), ".", ms=2.5, label=f"{step}: {len(batches)} calls")
        call += len(batches)
    axes.set_xlabel("call of the function (a column of points: one batch)")
    axes.set_ylabel("k [rad/m]")
    axes.set_title("The wavenumbers coatfft asked a UserFrf for, call by call")
    axes.legend(loc="upper right", markerscale=4)
    figure = os.path.join(args.out, "user_frf.png")
    fig.savefig(figure, dpi=110)
    print(f"figure: {figure}")

    for line in failures:
        print(f"FAILED: {line}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
