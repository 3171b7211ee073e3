#!/usr/bin/python3
"""A rough rigid sphere pressed into a coated body: a 50 um tungsten-carbide coating bonded on
steel, solved under load control, with maps of the pressure and the gap.

The body: the catalogue's tungsten carbide (E = 600 GPa, nu = 0.22) 50 um thick on steel
(210 GPa, 0.3), a hard coating of a thermal-spray thickness (sprayed WC-Co coatings are
typically 50-300 um thick and less stiff than the sintered carbide; the moduli here are
illustrative). The load: a sphere R = 10 mm at W = 100 N. Smooth, on bare steel, that contact
has the Hertz radius a = 0.148 mm and peak pressure 2.18 GPa (Johnson 1985, section 4.2), so the
coating is a third of the contact radius thick: the contact feels both materials. The script
solves the smooth sphere on the coated body too and prints it beside Hertz on bare steel and on
bare carbide, which is where the coating shows (computed: the equivalent contact radius
0.129 mm, 13 % below steel's and about half-way to carbide's 0.106 mm; the peak pressure
2.48 GPa, 14 % above steel's).

The roughness is that of examples/scenes/make_rough_sphere.py (the same heights, to rounding):
Gaussian white noise of numpy's default_rng (fixed seed), smoothed by a Gaussian of standard
deviation 3 cells in Fourier space so that every asperity spans several cells, scaled to an rms
height of 0.2 um. That is a tenth of the Hertz approach a^2/R = 2.2 um, which on bare steel
keeps it a rough Hertz contact (Greenwood & Tripp's alpha = sigma R / a^2 = 0.09, Johnson 1985
section 13.4; examples/scenes/rough_sphere_contact.toml: area 0.81 of the smooth one, peak
4.36 GPa). The stiffer coated body spreads the load less, so the roughness matters more
(computed: the rough contact covers 0.60 of the smooth coated contact's area, in patches, with
a peak of 8.5 GPa, 3.4 times the smooth one). The height passed to solve_contact is the gap to
the flat body: sphere minus roughness (the roughness positive towards the body), shifted so
that its smallest value is 0.

The operator is make_operator's "auto" choice, told the expected contact radius (load_radius)
and that a contact solve costs about 100 applications (applications=100, docs/auto.md
section 3); solve_contact is the preconditioned Polonsky & Keer (1999) iteration.

Run: /usr/bin/python3 examples/python/coated_rough_contact.py [--out DIR]
(with PYTHONPATH=build/python unless coatfft is installed). Writes coated_rough_contact.png
(pressure and gap maps) into DIR, by default out/python/ under the current directory. Exit
status 1 unless both solves converge without reaching the domain edge.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import PowerNorm  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import numpy as np  # noqa: E402

import coatfft  # noqa: E402

N = 128  # cells per side
L = 0.8e-3  # domain side [m]: more than five Hertz radii
R = 10e-3  # sphere radius [m]
W = 100.0  # load [N]
THICKNESS = 50e-6  # coating thickness [m]
RMS = 0.2e-6  # rms roughness [m]
SMOOTHING_CELLS = 3.0  # standard deviation of the roughness filter [cells]
SEED = 20240611


def hertz(E_star):
    """Contact radius [m], peak pressure [Pa] and approach [m] of the smooth sphere on a
    half-space of plane-strain modulus E_star (rigid sphere; Johnson 1985, eqs. 4.22-4.24)."""
    a = (3 * W * R / (4 * E_star)) ** (1 / 3)
    return a, 3 * W / (2 * math.pi * a * a), a * a / R


def roughness(grid):
    """Seeded Gaussian-smoothed random heights [m] of zero mean and rms RMS, shape (ny, nx)."""
    noise = np.random.default_rng(SEED).standard_normal(grid.shape)
    kx = 2 * np.pi * np.fft.fftfreq(grid.nx, d=grid.dx)
    ky = 2 * np.pi * np.fft.fftfreq(grid.ny, d=grid.dy)
    KX, KY = np.meshgrid(kx, ky)
    s = SMOOTHING_CELLS * grid.dx
    z = np.fft.ifft2(np.fft.fft2(noise) * np.exp(-0.5 * s * s * (KX**2 + KY**2))).real
    z -= z.mean()
    return z * (RMS / np.sqrt(np.mean(z * z)))


def report(label, result):
    print(f"{label}: load {result.load:.2f} N, contact area {result.contact_area * 1e6:.5f} mm^2 "
          f"(equivalent radius {result.contact_radius * 1e3:.4f} mm), max pressure "
          f"{result.max_pressure / 1e9:.3f} GPa, approach {result.approach * 1e6:.3f} um, "
          f"{result.iterations} iterations, status {result.status}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "python"),
                        help="folder for the figure (default: out/python)")
    args = parser.parse_args()

    steel = coatfft.material("steel")
    carbide = coatfft.material("tungsten_carbide")
    body = coatfft.LayerStack(steel, [coatfft.Coating(carbide, THICKNESS)])
    grid = coatfft.Grid(N, N, L, L)

    a_steel, p0_steel, delta_steel = hertz(steel.E_star)
    a_carbide, p0_carbide, _ = hertz(carbide.E_star)
    print(f"Hertz, bare steel:   a = {a_steel * 1e3:.4f} mm, p0 = {p0_steel / 1e9:.3f} GPa, "
          f"approach {delta_steel * 1e6:.3f} um")
    print(f"Hertz, bare carbide: a = {a_carbide * 1e3:.4f} mm, p0 = {p0_carbide / 1e9:.3f} GPa")
    print(f"coating: {THICKNESS * 1e6:g} um = {THICKNESS / a_steel:.2f} a (steel)")

    op = coatfft.make_operator(grid, body, load_radius=a_steel, applications=100)
    print(f"operator: {op.method}, setup {op.report['setup_seconds'] * 1e3:.1f} ms "
          f"(auto: {op.report['auto']['why']})")

    x, y = np.meshgrid(grid.x, grid.y)  # (ny, nx)
    r2 = x * x + y * y
    sphere = r2 / (R + np.sqrt(R * R - r2))  # R - sqrt(R^2 - r^2), without cancellation
    height = sphere - roughness(grid)
    height -= height.min()

    smooth = coatfft.solve_contact(op, sphere, load=W)
    report("smooth sphere, coated", smooth)
    rough = coatfft.solve_contact(op, height, load=W)
    report("rough sphere, coated ", rough)
    print(f"coated smooth against bare steel: contact radius x "
          f"{smooth.contact_radius / a_steel:.3f}, max pressure x "
          f"{smooth.max_pressure / p0_steel:.3f}")
    print(f"rough against smooth (coated): area x {rough.contact_area / smooth.contact_area:.3f}, "
          f"max pressure x {rough.max_pressure / smooth.max_pressure:.3f}")

    os.makedirs(args.out, exist_ok=True)
    extent = np.array([grid.x[0] - grid.dx / 2, grid.x[-1] + grid.dx / 2,
                       grid.y[0] - grid.dy / 2, grid.y[-1] + grid.dy / 2]) * 1e6  # um
    half = 2.0 * a_steel * 1e6  # the plotted window [um]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 5), constrained_layout=True)
    # Row j is y_j: origin="lower" puts y upwards.
    image = left.imshow(rough.pressure / 1e9, origin="lower", extent=extent, cmap="inferno")
    fig.colorbar(image, ax=left, label="pressure [GPa]")
    left.set_title("contact pressure")
    gap_um = rough.gap * 1e6
    # A square-root colour scale up to the approach: the gaps between the contact patches are
    # tenths of a micrometre, those outside the contact grow to microns.
    image = right.imshow(gap_um, origin="lower", extent=extent, cmap="viridis",
                         norm=PowerNorm(0.5, vmin=0, vmax=rough.approach * 1e6))
    fig.colorbar(image, ax=right, label="gap [um]", extend="max")
    right.contour(grid.x * 1e6, grid.y * 1e6, (rough.pressure > 0).astype(float),
                  levels=[0.5], colors="w", linewidths=0.7)
    right.set_title("gap (white: edges of the contact patches)")
    for axes in (left, right):
        axes.add_patch(Circle((0, 0), smooth.contact_radius * 1e6, fill=False, ls="--",
                              lw=0.9, color="c", label="smooth sphere's contact"))
        axes.set_xlim(-half, half)
        axes.set_ylim(-half, half)
        axes.set_xlabel("x [um]")
        axes.set_ylabel("y [um]")
    left.legend(loc="upper right", fontsize="small")
    fig.suptitle(f"Rough rigid sphere (R = {R * 1e3:g} mm, rms {RMS * 1e6:g} um) at {W:g} N on "
                 f"{THICKNESS * 1e6:g} um WC bonded on steel\ncontact area "
                 f"{rough.contact_area * 1e6:.4f} mm^2, max pressure "
                 f"{rough.max_pressure / 1e9:.2f} GPa")
    figure = os.path.join(args.out, "coated_rough_contact.png")
    fig.savefig(figure, dpi=110)
    print(f"figure: {figure}")

    failed = [f"{label}: {r.warning or r.status}" for label, r in (("smooth", smooth),
                                                                   ("rough", rough))
              if not r.converged or r.touches_boundary]
    for line in failed:
        print(f"FAILED: {line}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
