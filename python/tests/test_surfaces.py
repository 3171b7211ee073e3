"""Rough surfaces, indenter shapes, Hertz's closed forms, sweeps and stress invariants from
Python: each against the program or a closed form."""
import subprocess

import numpy as np
import pytest

import coatfft


def test_self_affine_surface_equals_the_program(coatfft_exe, tmp_path):
    # nx != ny: the (ny, nx) orientation is checked too. Bit for bit, both rms choices.
    grid = coatfft.Grid(48, 32, 1.5e-3, 1e-3)
    cases = [
        (dict(hurst=0.7, rms_slope=0.05, seed=2**64 - 1), ["--hurst", "0.7", "--rms-slope", "0.05",
                                                          "--seed", str(2**64 - 1)]),
        (dict(hurst=0.9, rms_height=1e-6, short_cutoff=1e-4, long_cutoff=5e-4, seed=7),
         ["--hurst", "0.9", "--rms-height", "1e-6", "--short-cutoff", "1e-4",
          "--long-cutoff", "5e-4", "--seed", "7"]),
    ]
    for k, (keywords, flags) in enumerate(cases):
        out = tmp_path / f"h{k}.npy"
        subprocess.run([coatfft_exe, "surface", "-o", str(out), "--nx", "48", "--ny", "32",
                        "--lx", "1.5e-3", "--ly", "1e-3", *flags], check=True,
                       capture_output=True)
        h = coatfft.self_affine_surface(grid, **keywords)
        assert h.shape == (32, 48)
        assert np.array_equal(h, np.load(out))
    # The rms slope asked for is the surface's (its spectral slope: to rounding).
    h = coatfft.self_affine_surface(grid, hurst=0.8, rms_height=2e-6)
    assert np.sqrt(np.mean((h - h.mean()) ** 2)) == pytest.approx(2e-6, rel=1e-12)


def test_self_affine_surface_refusals():
    grid = coatfft.Grid(32, 32, 1e-3, 1e-3)
    for seed in (-1, 2**64):
        with pytest.raises(ValueError, match=r"seed = .* must be an integer in 0 \.\. 2\^64 - 1"):
            coatfft.self_affine_surface(grid, hurst=0.8, rms_slope=0.1, seed=seed)
    with pytest.raises(ValueError, match="rms"):
        coatfft.self_affine_surface(grid, hurst=0.8, rms_slope=0.1, rms_height=1e-6)
    with pytest.raises(ValueError, match="rms"):
        coatfft.self_affine_surface(grid, hurst=0.8)


def test_indenter_heights_against_their_formulas():
    grid = coatfft.Grid(33, 21, 2e-3, 1e-3)
    x, y = np.meshgrid(grid.x, grid.y)  # (ny, nx)
    r = np.hypot(x, y)
    R = 5e-3
    # R - sqrt(R^2 - r^2) without its cancellation: r^2 / (R + sqrt(R^2 - r^2)).
    assert np.allclose(coatfft.sphere_height(grid, R), r * r / (R + np.sqrt(R * R - r * r)),
                       rtol=1e-14, atol=0)
    assert np.allclose(coatfft.paraboloid_height(grid, R), r * r / (2 * R), rtol=1e-14, atol=0)
    L, Re = 1e-3, 2e-2
    expected = y * y / (2 * R) + np.maximum(np.abs(x) - L / 2, 0) ** 2 / (2 * Re)
    assert np.allclose(coatfft.cylinder_height(grid, R, flat_length=L, end_radius=Re), expected,
                       rtol=1e-14, atol=0)
    a, rho = 4e-4, 1e-3
    expected = np.where(r <= a, 0.0, (r - a) ** 2 / (2 * rho))
    assert np.allclose(coatfft.flat_punch_height(grid, a, edge_radius=rho), expected, rtol=1e-14,
                       atol=0)
    with pytest.raises(ValueError):
        coatfft.sphere_height(grid, 1e-4)  # smaller than the domain: no surface at its corners
    with pytest.raises(ValueError):
        coatfft.paraboloid_height(grid, -1.0)


def test_hertz_sphere_against_johnson():
    R, E_star, W = 0.01, 115e9, 100.0
    h = coatfft.hertz_sphere(R, E_star, load=W)
    a = (3 * W * R / (4 * E_star)) ** (1 / 3)  # Johnson (1985) eqs. 4.22-4.23
    assert h["contact_radius"] == pytest.approx(a, rel=1e-14)
    assert h["max_pressure"] == pytest.approx(3 * W / (2 * np.pi * a * a), rel=1e-14)
    assert h["approach"] == pytest.approx(a * a / R, rel=1e-14)
    back = coatfft.hertz_sphere(R, E_star, approach=h["approach"])
    assert back["load"] == pytest.approx(W, rel=1e-13)
    with pytest.raises(ValueError, match="exactly one of load"):
        coatfft.hertz_sphere(R, E_star)
    with pytest.raises(ValueError, match="exactly one of load"):
        coatfft.hertz_sphere(R, E_star, load=W, approach=1e-6)


def test_solve_sweep_equals_the_separate_solves(steel):
    grid = coatfft.Grid(64, 64, 1e-3, 1e-3)
    op = coatfft.make_operator(grid, steel, boundary="periodic")
    z = coatfft.self_affine_surface(grid, hurst=0.8, rms_slope=0.05, short_cutoff=8 * grid.dx,
                                    seed=7)
    gap = z.max() - z
    loads = [400.0, 25.0, 100.0, 50.0, 200.0]
    sweep = coatfft.solve_sweep(op, gap, loads=loads)
    assert [r.load for r in sweep] == pytest.approx(sorted(loads), rel=1e-12)
    applications = 0
    for result, load in zip(sweep, sorted(loads)):
        alone = coatfft.solve_contact(op, gap, load=load)
        assert result.converged and alone.converged
        assert np.abs(result.pressure - alone.pressure).max() < 1e-8 * alone.max_pressure
        applications += alone.operator_applications
    assert sum(r.operator_applications for r in sweep) < applications
    approaches = [0.1 * gap.mean(), 0.2 * gap.mean()]
    by_approach = coatfft.solve_sweep(op, gap, approaches=approaches)
    assert [r.approach for r in by_approach] == pytest.approx(approaches, rel=1e-14)
    with pytest.raises(ValueError, match="exactly one of loads"):
        coatfft.solve_sweep(op, gap)
    with pytest.raises(ValueError, match="load"):
        coatfft.solve_sweep(op, gap, loads=[10.0, -1.0])


def test_principal_stresses_and_tresca(steel):
    # Hand-computed tensors, components xx, yy, zz, yz, xz, xy on the third axis from the end.
    s = np.zeros((2, 6, 1, 1))
    s[0, :3, 0, 0] = [3.0, 1.0, 2.0]  # principal axes: 3, 2, 1
    s[1, 5, 0, 0] = 2.0               # pure shear xy = 2: principal 2, 0, -2
    p = coatfft.principal_stresses(s)
    assert p.shape == (2, 3, 1, 1)
    assert np.allclose(p[0, :, 0, 0], [3.0, 2.0, 1.0], rtol=0, atol=1e-15)
    assert np.allclose(p[1, :, 0, 0], [2.0, 0.0, -2.0], rtol=0, atol=1e-15)
    assert np.allclose(coatfft.tresca(s)[:, 0, 0], [1.0, 2.0], rtol=0, atol=1e-15)
    # On stresses(): von Mises from the principal stresses, an identity of the invariants.
    grid = coatfft.Grid(16, 16, 4e-3, 4e-3)
    p0 = coatfft.hertz_pressure(grid, 1e9, 1e-3)
    stress = coatfft.stresses(steel, grid, [2e-4, 5e-4], p0, alpha=4)
    s1, s2, s3 = np.moveaxis(coatfft.principal_stresses(stress), -3, 0)
    vm = np.sqrt(((s1 - s2) ** 2 + (s2 - s3) ** 2 + (s3 - s1) ** 2) / 2)
    assert np.allclose(coatfft.von_mises(stress), vm, rtol=1e-12, atol=1e-9 * 1e9)
    assert np.allclose(coatfft.tresca(stress), (s1 - s3) / 2, rtol=0, atol=1e-6)
    assert np.all(s1 >= s2) and np.all(s2 >= s3)
    with pytest.raises(ValueError, match="tresca: the array needs the six components"):
        coatfft.tresca(np.zeros((5, 4, 4)))
