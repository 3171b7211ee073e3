#!/usr/bin/python3
"""A periodic rough surface pressed on 10 um of TiN bonded on steel: the area-load curve of a load
sweep, and the stresses in the coating and on its interface under the sliding contact's tractions.

The same problem as examples/scenes/rough_coated_sliding.toml, from Python: the flat rigid
counterface against the periodic self-affine topography of `coatfft surface` (H = 0.8, rms height
0.2 um, shortest wavelength 31.25 um, roll-off 125 um, seed 11; 128^2 cells over 0.5 mm), made here
by coatfft.self_affine_surface and checked equal, bit for bit, to the scene's
rough_coated_gap.npy. The operator is the periodic one of the coated body
(make_operator(..., boundary="periodic"): frf-split's exact periodic kernel), so the topography
repeats with no domain edge.

1. A load sweep from 1.25 N to 12.5 N (mean pressures 5 to 50 MPa) by solve_sweep: one operator,
   each load started from the ones before it. The real area grows almost linearly with the load
   (Persson 2001: A/A0 = erf(sqrt(2) p/(E* s)), about sqrt(8/pi) p/(E* s) at small p).
2. At 12.5 N, the stresses at the interface (both sides) and at mid-coating under the frictionless
   pressure and the tractions q_x = 0.3 p of full sliding (stresses(..., boundary="periodic")).
   run_scene of the scene solves the same contact with the tractions' normal displacement coupled
   into the gap; its pressure moves by about a tenth of the peak, and the script prints both
   interface maxima beside each other.

Checked (exit status 1 otherwise): the surface equals the scene's gap; every solve converged;
the area grows with the load; the equilibrium of the periodic body: on every plane the mean of
sigma_zz is minus the mean pressure and that of sigma_xz minus the mean traction, within 1e-9 (the
k -> 0 limit's evaluation, docs/stress.md).

Run: /usr/bin/python3 examples/python/rough_coated_stresses.py [--out DIR]
(with PYTHONPATH=build/python unless coatfft is installed). Writes rough_coated_stresses.png
(area-load curve, pressure map, von Mises on the interface) into DIR (default out/python/).
"""
import argparse
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import coatfft  # noqa: E402

SCENES = pathlib.Path(__file__).resolve().parent.parent / "scenes"
N, L = 128, 0.5e-3  # cells per side, period [m]
THICKNESS = 10e-6  # TiN coating [m]
MU = 0.3  # friction coefficient of full sliding
LOADS = np.linspace(1.25, 12.5, 10)  # N


def surface(grid):
    """The gap to the flat body [m], (ny, nx): max(z) - z of the scene's topography."""
    z = coatfft.self_affine_surface(grid, hurst=0.8, rms_height=0.2e-6, short_cutoff=3.125e-5,
                                    long_cutoff=1.25e-4, seed=11)
    return z.max() - z


def equilibrium_error(stress, p, qx):
    """Largest |mean sigma_zz + mean p| and |mean sigma_xz + mean q_x| over the planes, over the
    mean pressure."""
    szz = stress[:, 2].mean(axis=(1, 2)) + p.mean()
    sxz = stress[:, 4].mean(axis=(1, 2)) + qx.mean()
    return max(np.abs(szz).max(), np.abs(sxz).max()) / p.mean()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "python"),
                        help="folder for the figure (default: out/python)")
    args = parser.parse_args()
    ok = True

    steel, tin = coatfft.material("steel"), coatfft.material("titanium_nitride")
    body = coatfft.LayerStack(steel, [coatfft.Coating(tin, THICKNESS)])
    grid = coatfft.Grid(N, N, L, L)
    gap = surface(grid)
    same = np.array_equal(gap, np.load(SCENES / "rough_coated_gap.npy"))
    print(f"surface equal to the scene's rough_coated_gap.npy: {same}")
    ok &= same

    op = coatfft.make_operator(grid, body, boundary="periodic")
    print(f"operator: {op.method} (periodic), setup {op.report['setup_seconds'] * 1e3:.1f} ms")
    sweep = coatfft.solve_sweep(op, gap, loads=list(LOADS))
    area = np.array([r.contact_area / (L * L) for r in sweep])
    for w, a, r in zip(LOADS, area, sweep):
        print(f"  load {w:6.2f} N: area {100 * a:5.2f} %, max pressure "
              f"{r.max_pressure / 1e9:5.2f} GPa, {r.operator_applications} applications, "
              f"{r.status}")
    ok &= all(r.status == "converged" for r in sweep) and bool(np.all(np.diff(area) > 0))

    p = sweep[-1].pressure
    depths = [THICKNESS / 2, THICKNESS]
    coating_side = coatfft.stresses(body, grid, depths, p, qx=MU * p, boundary="periodic",
                                    at_interface="above")
    substrate_side = coatfft.stresses(body, grid, [THICKNESS], p, qx=MU * p,
                                      boundary="periodic", at_interface="below")
    error = max(equilibrium_error(coating_side, p, MU * p),
                equilibrium_error(substrate_side, p, MU * p))
    print(f"equilibrium of the planes: {error:.1e} of the mean pressure")
    ok &= error < 1e-9
    mises_mid, mises_top = coatfft.von_mises(coating_side)
    mises_bottom = coatfft.von_mises(substrate_side)[0]
    print(f"largest von Mises: mid-coating {mises_mid.max() / 1e6:.0f} MPa, interface "
          f"{mises_top.max() / 1e6:.0f} MPa (coating side), {mises_bottom.max() / 1e6:.0f} MPa "
          f"(steel side); largest tension in the coating on the interface "
          f"{coatfft.principal_stresses(coating_side[1])[0].max() / 1e6:.0f} MPa")

    run = coatfft.run_scene(str(SCENES / "rough_coated_sliding.toml"))
    coupled = run["summary"]
    layers = {layer["medium"]: layer for layer in coupled["stress"]["layers"]}
    print(f"the scene (friction coupled, {coupled['friction_coupling']['solves']} normal "
          f"solves): pressure moved by {100 * coupled['friction_coupling']['pressure_shift']:.1f} "
          f"% of its peak; largest von Mises in the coating "
          f"{layers['coating 1']['max_von_mises']['value'] / 1e6:.0f} MPa, in the steel "
          f"{layers['substrate']['max_von_mises']['value'] / 1e6:.0f} MPa")
    ok &= coupled["converged"] and coupled["friction_coupling"]["converged"]

    os.makedirs(args.out, exist_ok=True)
    extent = np.array([grid.x[0], grid.x[-1], grid.y[0], grid.y[-1]]) * 1e6  # um
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    axes[0].plot(LOADS / (L * L) / 1e6, 100 * area, "o-")
    axes[0].set_xlabel("mean pressure [MPa]")
    axes[0].set_ylabel("real contact area [%]")
    axes[0].set_title("area-load curve (solve_sweep)")
    image = axes[1].imshow(p / 1e9, origin="lower", extent=extent, cmap="inferno")
    fig.colorbar(image, ax=axes[1], label="pressure [GPa]")
    axes[1].set_title(f"pressure at {LOADS[-1]:g} N")
    image = axes[2].imshow(mises_top / 1e6, origin="lower", extent=extent, cmap="magma")
    fig.colorbar(image, ax=axes[2], label="von Mises [MPa]")
    axes[2].set_title(f"interface z = {THICKNESS * 1e6:g} um, coating side, mu = {MU}")
    for a in axes[1:]:
        a.set_xlabel("x [um]")
        a.set_ylabel("y [um]")
    path = os.path.join(args.out, "rough_coated_stresses.png")
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
