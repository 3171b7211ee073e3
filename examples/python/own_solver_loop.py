#!/usr/bin/python3
"""coatfft's operator of a coated body inside a contact solver written in numpy: the user owns
the loop, coatfft gives the displacement u = K p of each iterate (Operator.apply).

The problem: a rigid sphere (R = 10 mm) pressed with W = 2 N on a compliant coating (the
catalogue's PEEK, E = 3.7 GPa, nu = 0.4, 20 um thick) bonded on steel. The coating is a fifth
of the contact radius thick, so the body is neither material: the contact radius (computed:
93 um) lies between Hertz's on bare PEEK (150 um) and on bare steel (40 um), and the peak
pressure (142 MPa) between theirs (42 and 591 MPa; Johnson 1985, section 4.2).

The loop, `constrained_cg` below, is the constrained conjugate gradient of Polonsky & Keer
(1999) under load control, in its classic (unpreconditioned) form, in a few lines of numpy: two
operator applications per iteration, the contact set from the sign of the pressure, the load
imposed by rescaling. Any other solver (a projected gradient, an augmented Lagrangian, ...)
would call op.apply the same way. solve_contact runs the library's own, preconditioned,
version of the same iteration on the same operator.

The check: both solve one discrete problem, the complementarity conditions p >= 0, g >= 0,
p g = 0 with sum p dx dy = W, whose solution is unique (K is symmetric positive definite: the
problem is a strictly convex quadratic programme, docs/contact.md). So the two pressures differ
only by what each iteration leaves at its stopping rule, the relative pressure change of one
iteration below 1e-10. The script also stops its loop at 1e-4 ... 1e-8 to show the difference
following the stopping tolerance (computed, relative to max p: 2.8e-4 at 1e-4, 2.8e-6 at 1e-6,
3.1e-8 at 1e-8, 1.5e-10 at 1e-10). The difference was at most 14 times the tolerance over the
bodies tried while writing this script (TiN 2 and 20 um, WC 50 um, aluminium and PEEK 20 um on
steel, 128^2 cells). The check is a difference below 1e-7 of max p at 1e-10: 70 times the worst
of those.

Run: /usr/bin/python3 examples/python/own_solver_loop.py [--out DIR]
(with PYTHONPATH=build/python unless coatfft is installed). Writes own_solver_loop.png (the
loop's convergence and the two pressure profiles) into DIR, by default out/python/ under the
current directory. Exit status 1 when the check fails or a solve does not converge.
"""
import argparse
import math
import os
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import coatfft  # noqa: E402

N = 128  # cells per side
L = 0.4e-3  # domain side [m]
R = 10e-3  # sphere radius [m]
W = 2.0  # load [N]
THICKNESS = 20e-6  # coating thickness [m]
TOLERANCE = 1e-10  # stopping rule of both solvers
BOUND = 1e-7  # the check: max |p_loop - p_coatfft| / max p_coatfft


def constrained_cg(apply, height, load, cell_area, tolerance, max_iterations=1000):
    """Polonsky & Keer's (1999) constrained conjugate gradient under load control.

    apply(p) -> u: the surface displacement [m] of a pressure [Pa], arrays of one shape.
    height: the initial gap h [m]; load: the total force [N]; cell_area: dx dy [m^2].
    Returns the pressure, the number of iterations and the residual of each iteration (the
    relative pressure change, sum |p_new - p_old| / sum p_new).
    """
    p = np.full(height.shape, load / (height.size * cell_area))  # uniform start
    t = np.zeros_like(p)
    g_norm_old = 1.0
    restart = True
    history = []
    for iteration in range(1, max_iterations + 1):
        contact = p > 0
        g = height + apply(p)
        g -= g[contact].mean()  # the current approach, removed: g = h + u - delta
        g_norm = float(np.sum(g[contact] ** 2))
        beta = 0.0 if restart else g_norm / g_norm_old
        t = np.where(contact, g + beta * t, 0.0)  # conjugate direction on the contact set
        g_norm_old = g_norm
        r = apply(t)
        r -= r[contact].mean()
        step = float(np.sum(g[contact] * t[contact]) / np.sum(r[contact] * t[contact]))
        p_old = p
        p = np.maximum(p - step * t, 0.0)
        overlap = ~contact & (g < 0)  # cells outside the contact that the indenter penetrates
        p[overlap] = -step * g[overlap]
        restart = bool(overlap.any())  # new contact cells: the next direction starts afresh
        p *= load / (p.sum() * cell_area)
        history.append(float(np.abs(p - p_old).sum() / p.sum()))
        if history[-1] < tolerance:
            break
    return p, iteration, history


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "python"),
                        help="folder for the figure (default: out/python)")
    args = parser.parse_args()

    steel = coatfft.material("steel")
    peek = coatfft.material("peek")
    body = coatfft.LayerStack(steel, [coatfft.Coating(peek, THICKNESS)])
    grid = coatfft.Grid(N, N, L, L)
    for name, m in (("PEEK", peek), ("steel", steel)):
        a = (3 * W * R / (4 * m.E_star)) ** (1 / 3)
        print(f"Hertz on bare {name}: a = {a * 1e6:.1f} um, "
              f"p0 = {3 * W / (2 * math.pi * a * a) / 1e6:.1f} MPa")

    op = coatfft.make_operator(grid, body, load_radius=0.1e-3, applications=100)
    print(f"operator: {op.method}, setup {op.report['setup_seconds'] * 1e3:.1f} ms")

    x, y = np.meshgrid(grid.x, grid.y)  # (ny, nx)
    r2 = x * x + y * y
    sphere = r2 / (R + np.sqrt(R * R - r2))  # R - sqrt(R^2 - r^2)
    cell_area = grid.dx * grid.dy

    applications = 0

    def apply(p):
        nonlocal applications
        applications += 1
        return op.apply(p)

    start = time.perf_counter()
    p_loop, iterations, history = constrained_cg(apply, sphere, W, cell_area, TOLERANCE)
    seconds = time.perf_counter() - start
    print(f"numpy loop: {iterations} iterations, {applications} calls of op.apply, "
          f"{seconds * 1e3:.0f} ms ({seconds / applications * 1e6:.0f} us per call, the numpy "
          f"work included), residual {history[-1]:.1e}")

    start = time.perf_counter()
    ref = coatfft.solve_contact(op, sphere, load=W, tolerance=TOLERANCE)
    seconds = time.perf_counter() - start
    print(f"solve_contact: {ref.iterations} iterations, {seconds * 1e3:.0f} ms, status "
          f"{ref.status}; contact radius {ref.contact_radius * 1e6:.1f} um, max pressure "
          f"{ref.max_pressure / 1e6:.1f} MPa, approach {ref.approach * 1e6:.4f} um")

    print("max |p_loop - p_coatfft| / max p_coatfft, by the loop's stopping tolerance:")
    difference = {}
    for tolerance in (1e-4, 1e-6, 1e-8, TOLERANCE):
        p, its, _ = ((p_loop, iterations, None) if tolerance == TOLERANCE else
                     constrained_cg(op.apply, sphere, W, cell_area, tolerance))
        difference[tolerance] = float(np.abs(p - ref.pressure).max() / ref.max_pressure)
        print(f"  {tolerance:.0e}: {difference[tolerance]:.2e} ({its} iterations)")
    cells = int(np.count_nonzero((p_loop > 0) != (ref.pressure > 0)))
    print(f"contact cells: {np.count_nonzero(ref.pressure > 0)}, {cells} where the two differ")
    print(f"difference at {TOLERANCE:.0e}: {difference[TOLERANCE]:.2e} (bound {BOUND:.0e})")

    os.makedirs(args.out, exist_ok=True)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True)
    left.semilogy(range(1, len(history) + 1), history, "C0.-")
    left.axhline(TOLERANCE, color="0.5", ls="--", lw=1, label="stopping tolerance")
    left.set_xlabel("iteration of the numpy loop")
    left.set_ylabel("relative pressure change")
    left.set_title("Polonsky & Keer (1999) in numpy, K p = op.apply(p)")
    left.legend()
    row = int(np.argmin(np.abs(grid.y)))  # the row nearest y = 0
    right.plot(grid.x * 1e6, ref.pressure[row] / 1e6, "k-", lw=1.5, label="solve_contact")
    right.plot(grid.x * 1e6, p_loop[row] / 1e6, "C1.", ms=4, label="numpy loop")
    right.set_xlabel(f"x [um] (y = {grid.y[row] * 1e6:.2f} um)")
    right.set_ylabel("pressure [MPa]")
    right.set_title(f"sphere R = {R * 1e3:g} mm, {W:g} N, {THICKNESS * 1e6:g} um PEEK on steel")
    right.legend()
    figure = os.path.join(args.out, "own_solver_loop.png")
    fig.savefig(figure, dpi=110)
    print(f"figure: {figure}")

    failures = []
    if not difference[TOLERANCE] < BOUND:
        failures.append(f"difference {difference[TOLERANCE]:.2e} not below {BOUND:.0e}")
    if history[-1] >= TOLERANCE:
        failures.append(f"the numpy loop did not converge (residual {history[-1]:.1e})")
    if not ref.converged or ref.touches_boundary:
        failures.append(f"solve_contact: {ref.warning}")
    for line in failures:
        print(f"FAILED: {line}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
