#!/usr/bin/python3
"""How a hard coating changes the stresses below a Hertz contact: the section y = 0 of the von
Mises stress in a steel half-space and in the same steel under 50 um of TiN, under the same
Hertz pressure.

A Hertz pressure (p0 = 1 GPa, a = 0.5 mm) is cell-averaged on an N x N grid over [-2a, 2a]^2
(N = 97 by default) and coatfft.stresses computes the six stresses on planes z = a/20 ... 2a
(40 planes) of each body; their rows y = 0 make the section. For the half-space the shear stress
(sigma_1 - sigma_3)/2 on the axis has Johnson's (1985) closed form (eq. 3.45; largest, 0.310 p0,
at z = 0.48a); the check is that form within 1e-3 p0 on every plane from z = a/4 down (the load
is discretised at dx = a/24: docs/validation/stress.md measures 4e-4 p0 at a/32, 1.6e-3 at
a/16, at z = a/4).

Run: /usr/bin/python3 examples/python/coating_stresses.py [--out DIR] [--n N]
(with PYTHONPATH=build/python unless coatfft is installed). Writes coating_stresses.png (the two
sections) into DIR, by default out/python/. Exit status 1 when the check fails.
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
A = 0.5e-3  # contact radius [m]


def johnson_axis_shear(z, nu):
    """(sigma_r - sigma_z)/2 [p0] on the axis of a Hertz pressure (Johnson 1985, eq. 3.45)."""
    zeta = z / A
    szz = -1 / (1 + zeta**2)
    srr = -((1 + nu) * (1 - zeta * np.arctan(1 / zeta)) - 0.5 / (1 + zeta**2))
    return 0.5 * (srr - szz)


def section(body, grid, pressure, depths):
    """von Mises on y = 0 (rows: depths) and the largest shear on the axis, per depth."""
    s = coatfft.stresses(body, grid, list(depths), pressure)
    j = i = grid.nx // 2  # the centre cell (N odd)
    vm = coatfft.von_mises(s)[:, j, :]
    sxx, syy, szz = s[:, 0, j, i], s[:, 1, j, i], s[:, 2, j, i]
    tau_axis = 0.5 * (np.maximum(sxx, syy) - szz)  # principal axes on the axis: x, y, z
    return vm, tau_axis


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "python"),
                        help="folder for the figure (default: out/python)")
    parser.add_argument("--n", type=int, default=97, help="cells per side, odd (default 97)")
    parser.add_argument("--nz", type=int, default=40,
                        help="depths, evenly from 2 a / nz to 2 a (default 40)")
    args = parser.parse_args()
    if args.n % 2 == 0:
        sys.exit("--n must be odd (a cell centred on the axis)")
    if args.nz < 8:
        sys.exit("--nz must be at least 8 (the check compares the depths z >= a/4)")

    steel = coatfft.material("steel")
    tin = coatfft.Coating(coatfft.material("titanium_nitride"), 50e-6)
    grid = coatfft.Grid(args.n, args.n, 4 * A, 4 * A)
    p = coatfft.hertz_pressure(grid, P0, A, "cell_average")
    depths = 2 * A * np.arange(1, args.nz + 1) / args.nz
    bodies = {"steel": steel, "50 um TiN on steel": coatfft.LayerStack(steel, [tin])}
    results = {name: section(body, grid, p, depths) for name, body in bodies.items()}

    tau = results["steel"][1] / P0
    k = int(np.argmax(tau))
    print(f"steel: largest shear on the axis {tau[k]:.4f} p0 at z = {depths[k] / A:.2f} a "
          "(Johnson: 0.310 p0 at 0.48 a)")
    for name, (vm, _) in results.items():
        jz, ix = np.unravel_index(np.argmax(vm), vm.shape)
        print(f"{name}: largest von Mises on y = 0 {vm.max() / P0:.4f} p0 at "
              f"x = {grid.x[ix] / A:+.2f} a, z = {depths[jz] / A:.2f} a")

    os.makedirs(args.out, exist_ok=True)
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.4), sharey=True)
    for ax, (name, (vm, _)) in zip(axes, results.items()):
        mesh = ax.pcolormesh(grid.x / A, depths / A, vm / P0, shading="nearest", vmax=0.75)
        ax.set_title(name)
        ax.set_xlabel("x / a")
    axes[0].set_ylabel("z / a")
    axes[0].invert_yaxis()
    fig.colorbar(mesh, ax=axes, label="von Mises / p0")
    path = os.path.join(args.out, "coating_stresses.png")
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")

    deep = depths >= A / 4
    worst = float(np.abs(tau[deep] - johnson_axis_shear(depths[deep], steel.nu)).max())
    print(f"steel: shear on the axis against Johnson eq. 3.45, z >= a/4: {worst:.2e} p0")
    ok = worst < 1e-3
    if not ok:
        print("check failed: the half-space's shear on the axis is not Johnson's")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
