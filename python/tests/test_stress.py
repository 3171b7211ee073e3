"""stresses and von_mises: against Johnson's (1985) eq. 3.45 on the axis of a Hertz pressure,
against the program (`coatfft run` of the [stress] example scene: run_scene and stresses give
its files exactly), linearity in the tractions, and the errors."""
import subprocess

import numpy as np
import pytest

import coatfft
from conftest import SCENES


def hertz_case(n=65):
    grid = coatfft.Grid(n, n, 4e-3, 4e-3)
    return grid, coatfft.hertz_pressure(grid, 1.0, 1e-3, "cell_average")


def test_axis_against_johnson(steel):
    grid, p = hertz_case()
    z = np.array([0.25, 0.5, 1.0])
    s = coatfft.stresses(steel, grid, list(z * 1e-3), p)
    assert s.shape == (3, 6, 65, 65)
    nu = steel.nu
    szz = -1 / (1 + z**2)
    srr = -((1 + nu) * (1 - z * np.arctan(1 / z)) - 0.5 / (1 + z**2))
    # The load's discretisation at a/16 (7e-4 of p0 for sigma_zz, docs/stress.md).
    assert np.abs(s[:, 2, 32, 32] - szz).max() < 1e-3
    assert np.abs(s[:, 0, 32, 32] - srr).max() < 1e-3
    assert np.abs(s[:, 1, 32, 32] - srr).max() < 1e-3
    assert np.abs(s[:, 4, 32, 32]).max() < 1e-14  # no shear on the axis


def test_von_mises_formula():
    rng = np.random.default_rng(3)
    s = rng.normal(size=(2, 6, 4, 5))
    xx, yy, zz, yz, xz, xy = s[:, 0], s[:, 1], s[:, 2], s[:, 3], s[:, 4], s[:, 5]
    expected = np.sqrt(0.5 * ((xx - yy)**2 + (yy - zz)**2 + (zz - xx)**2)
                       + 3 * (yz**2 + xz**2 + xy**2))
    np.testing.assert_allclose(coatfft.von_mises(s), expected, rtol=1e-15, atol=0)
    assert coatfft.von_mises(s[0]).shape == (4, 5)
    # Scaled by the largest component: finite wherever the value is (the squares overflowed).
    big = coatfft.von_mises(s * 1e300)
    assert np.all(np.isfinite(big))
    np.testing.assert_allclose(big, expected * 1e300, rtol=1e-14, atol=0)


def test_equals_the_program(coatfft_exe, tmp_path, steel, tin):
    # The [stress] example on 33^2 cells, 8 section rows, alpha = 4 and without its shallowest
    # plane (whose kernels cost most): the equality is bitwise, so it depends on none of them,
    # and the example itself is run by the examples' test.
    text = (SCENES / "coated_hertz_stress.toml").read_text()
    # A 0.4 mm coating for its 0.1 mm: the in-plane surface kernels' cost grows like (L/h)^2.
    edits = [("nx = 97\nny = 97", "nx = 33\nny = 33"), ("nz = 40", "nz = 8"),
             ("alpha = 16", "alpha = 4"), ("[5.0e-5, 1.0e-4, 4.8e-4]", "[1.0e-4, 4.8e-4]"),
             ("thickness = 1.0e-4", "thickness = 4.0e-4")]
    small = text
    for old, new in edits:
        assert old in small
        small = small.replace(old, new)
    scene = tmp_path / "coated_hertz_stress.toml"
    scene.write_text(small)
    out = tmp_path / "out"
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(out), "--quiet"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    run = coatfft.run_scene(str(scene))
    for name in ("stress", "von_mises", "stress_section", "von_mises_section",
                 "stress_interfaces", "von_mises_interfaces"):
        np.testing.assert_array_equal(run[name], np.load(out / f"{name}.npy"))
    # The library call with the scene's body, load and depths gives the same planes.
    grid = coatfft.Grid(33, 33, 4e-3, 4e-3)
    body = coatfft.LayerStack(steel, [coatfft.Coating(tin, 4e-4)])
    s = coatfft.stresses(body, grid, [1e-4, 4.8e-4], run["pressure"], alpha=4)
    np.testing.assert_array_equal(s, run["stress"])
    np.testing.assert_array_equal(coatfft.von_mises(s), run["von_mises"])


def test_periodic_equals_the_program(coatfft_exe, tmp_path, steel, tin):
    # A periodic coated scene with [stress] and [shear]: run_scene, the program and stresses(...,
    # boundary="periodic"), surface_displacements(..., boundary="periodic") give the same planes
    # and in-plane displacements bitwise.
    text = (
        "[grid]\nnx = 32\nny = 32\nlx = 1e-3\nly = 1e-3\nboundary = \"periodic\"\n"
        "[substrate]\nmaterial = \"steel\"\n[[coating]]\nmaterial = \"titanium_nitride\"\n"
        "thickness = 1e-4\n[pressure]\nkind = \"hertz\"\np0 = 1e9\na = 2e-4\n"
        "[shear]\nkind = \"proportional\"\nmu = 0.2\n[stress]\ndepths = [1e-4, 2e-4]\n")
    scene = tmp_path / "periodic_stress.toml"
    scene.write_text(text)
    out = tmp_path / "out"
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(out), "--quiet"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    run = coatfft.run_scene(str(scene))
    for name in ("stress", "ux", "uy"):
        np.testing.assert_array_equal(run[name], np.load(out / f"{name}.npy"))
    assert run["summary"]["stress"]["periodic"] is True
    grid = coatfft.Grid(32, 32, 1e-3, 1e-3)
    body = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-4)])
    p = run["pressure"]
    s = coatfft.stresses(body, grid, [1e-4, 2e-4], p, qx=0.2 * p, boundary="periodic")
    np.testing.assert_array_equal(s, run["stress"])
    ux, uy, _ = coatfft.surface_displacements(body, grid, p, qx=0.2 * p, boundary="periodic")
    np.testing.assert_array_equal(ux, run["ux"])
    np.testing.assert_array_equal(uy, run["uy"])
    # Every periodic displacement has zero mean; sigma_xz balances the mean traction (to the
    # 1e-10 of the k -> 0 limit, taken at k L = 1e-10).
    assert abs(ux.mean()) < 1e-12 * np.abs(ux).max()
    np.testing.assert_allclose(s[:, 4].mean(axis=(1, 2)), -0.2 * p.mean(), rtol=1e-9)
    # Equilibrium of the slab above each plane: mean sigma_zz = -mean pressure.
    np.testing.assert_allclose(s[:, 2].mean(axis=(1, 2)), -run["pressure"].mean(), rtol=1e-12)


def test_periodic_errors(steel):
    grid, p = hertz_case(17)
    even = coatfft.Grid(16, 16, 1e-3, 1e-3)
    q = np.zeros((16, 16))
    with pytest.raises(ValueError, match="alpha"):
        coatfft.stresses(steel, even, [1e-4], q, boundary="periodic", alpha=8)
    with pytest.raises(ValueError, match="boundary"):
        coatfft.stresses(steel, even, [1e-4], q, boundary="open")
    with pytest.raises(ValueError, match="even"):
        coatfft.stresses(steel, grid, [1e-4], p, boundary="periodic")
    with pytest.raises(ValueError, match="boundary"):
        coatfft.surface_displacements(steel, even, q, boundary="open")
    with pytest.raises(ValueError, match="even"):
        coatfft.surface_displacements(steel, grid, p, boundary="periodic")


def test_tractions_are_linear(steel):
    grid, p = hertz_case(33)
    base = coatfft.stresses(steel, grid, [3e-4], p, alpha=4)
    qx = coatfft.stresses(steel, grid, [3e-4], p, qx=0.3 * p, alpha=4)
    qy = coatfft.stresses(steel, grid, [3e-4], p, qy=0.3 * p, alpha=4)
    both = coatfft.stresses(steel, grid, [3e-4], p, qx=0.3 * p, qy=0.3 * p, alpha=4)
    np.testing.assert_allclose(both - base, (qx - base) + (qy - base), atol=1e-14, rtol=0)
    # Symmetry: q_y is q_x turned by 90 degrees on a square grid: sigma_yz(x, y) under q_y is
    # sigma_xz(y, x) under q_x.
    np.testing.assert_allclose((qy - base)[0, 3], (qx - base)[0, 4].T, atol=1e-14, rtol=0)


def test_typed_depth_on_a_running_sum_interface(steel, tin):
    # 10 um + 20 um = 3.0000000000000004e-05: the typed 30e-6, one ulp above, is that interface
    # (LayerStack::locate, a relative 256 DBL_EPSILON) on the side at_interface names.
    soft = coatfft.Material(50e9, 0.3)
    body = coatfft.LayerStack(steel, [coatfft.Coating(tin, 10e-6), coatfft.Coating(soft, 20e-6)])
    exact = body.interface_depths[1]
    assert body.interface_depths == [10e-6, 10e-6 + 20e-6]
    assert exact != 30e-6
    grid = coatfft.Grid(24, 20, 0.3e-3, 0.25e-3)
    p = coatfft.hertz_pressure(grid, 1e9, 0.1e-3, "cell_average")
    sides = {side: coatfft.stresses(body, grid, [30e-6, exact], p, at_interface=side, alpha=4)
             for side in ("above", "below")}
    for s in sides.values():
        # The interface's fields; the alias cut-offs (from the depths) differ by an ulp.
        np.testing.assert_allclose(s[0], s[1], atol=1e-3, rtol=0)  # Pa: 1e-12 of p0
    # The sides differ: sigma_xx jumps across the interface, by 6.7 % of p0.
    assert np.abs(sides["above"][0, 0] - sides["below"][0, 0]).max() > 3e7


def test_errors(steel, tin):
    grid, p = hertz_case(17)
    table = coatfft.TabulatedFrf(np.logspace(0, 8, 50), 1 / np.logspace(0, 8, 50) / 1e11)
    with pytest.raises(ValueError, match="not an Frf"):
        coatfft.stresses(table, grid, [1e-4], p)
    with pytest.raises(ValueError, match="at_interface"):
        coatfft.stresses(steel, grid, [1e-4], p, at_interface="middle")
    with pytest.raises(ValueError, match="depth"):
        coatfft.stresses(steel, grid, [-1e-4], p)
    # The surface plane is named as such, not as a kernel of infinite cost.
    with pytest.raises(ValueError, match=r"depth z = 0 m: every depth must be finite and > 0"):
        coatfft.stresses(steel, grid, [0.0], p)
    with pytest.raises(ValueError, match="shape"):
        coatfft.stresses(steel, grid, [1e-4], p[:-1])
    sliding = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-4, "frictionless")])
    with pytest.raises(ValueError, match="frictionless"):
        coatfft.stresses(sliding, grid, [1e-4], p, qx=p)
    with pytest.raises(ValueError, match="third axis"):
        coatfft.von_mises(np.zeros((5, 4, 3)))


def test_surface_displacements_against_johnson(steel):
    # The Hertz-type traction q0 sqrt(1 - r^2/a^2) along x on a half-space (Johnson 1985, section
    # 3.6): u_x = pi q0/(32 G a) [4 (2 - nu) a^2 - (4 - 3 nu) x^2 - (4 - nu) y^2] and
    # u_y = pi q0/(32 G a) 2 nu x y for r <= a. The cell-averaged load at a/16 leaves 1.4e-3 of
    # u_x(0) (docs/validation/traction.md); inside the contact less.
    grid, q = hertz_case()
    ux, uy, uz = coatfft.surface_displacements(steel, grid, np.zeros_like(q), qx=q)
    assert ux.shape == uy.shape == uz.shape == (65, 65)
    G, nu, a = steel.E / (2 * (1 + steel.nu)), steel.nu, 1e-3
    x, y = np.meshgrid(grid.x, grid.y)
    inside = x**2 + y**2 <= (0.9 * a)**2
    c = np.pi / (32 * G * a)
    ref_x = c * (4 * (2 - nu) * a**2 - (4 - 3 * nu) * x**2 - (4 - nu) * y**2)
    ref_y = c * 2 * nu * x * y
    scale = ref_x.max()
    assert np.abs(ux - ref_x)[inside].max() < 1.5e-3 * scale
    assert np.abs(uy - ref_y)[inside].max() < 1.5e-3 * scale
    # u_z under the traction is odd in x and, by Betti, minus u_x under the same load as a
    # pressure (the grid is symmetric about the origin).
    np.testing.assert_allclose(uz, -uz[:, ::-1], atol=1e-12 * scale)
    px, _, _ = coatfft.surface_displacements(steel, grid, q)
    np.testing.assert_allclose(uz, -px, atol=1e-12 * scale)


def test_surface_displacements_equal_the_program(coatfft_exe, tmp_path, steel, tin):
    # The [shear] example with a 0.4 mm coating for its 0.1 mm: the equality is bitwise, so it
    # does not depend on it, and the kernels' cost grows like (L/h)^2 (the example itself is run
    # by the examples' test).
    text = (SCENES / "coated_hertz_shear.toml").read_text()
    assert "thickness = 1.0e-4" in text
    scene = tmp_path / "coated_hertz_shear.toml"
    scene.write_text(text.replace("thickness = 1.0e-4", "thickness = 4.0e-4"))
    tmp_path = tmp_path / "out"
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(tmp_path), "--quiet"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    run = coatfft.run_scene(str(scene))
    for name in ("ux", "uy", "uz"):
        np.testing.assert_array_equal(run[name], np.load(tmp_path / f"{name}.npy"))
    grid = coatfft.Grid(65, 65, 4.0625e-3, 4.0625e-3)
    body = coatfft.LayerStack(steel, [coatfft.Coating(tin, 4e-4)])
    ux, uy, uz = coatfft.surface_displacements(body, grid, run["pressure"],
                                               qx=0.3 * run["pressure"])
    np.testing.assert_array_equal(ux, run["ux"])
    np.testing.assert_array_equal(uy, run["uy"])
    # The program's uz is frf-split's under p plus the tractions' share: the same kernels, summed
    # in another order.
    np.testing.assert_allclose(uz, run["uz"], rtol=0, atol=1e-12 * np.abs(uz).max())


def test_surface_displacements_errors(steel, tin):
    grid, p = hertz_case(17)
    table = coatfft.TabulatedFrf(np.logspace(0, 8, 50), 1 / np.logspace(0, 8, 50) / 1e11)
    with pytest.raises(ValueError, match="not an Frf"):
        coatfft.surface_displacements(table, grid, p)
    sliding = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-4, "frictionless")])
    with pytest.raises(ValueError, match="frictionless"):
        coatfft.surface_displacements(sliding, grid, p, qx=p)
    with pytest.raises(ValueError, match="shape"):
        coatfft.surface_displacements(steel, grid, p, qy=p[:-1])
    thin = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-8)])
    with pytest.raises(ValueError, match="FRF evaluations"):
        coatfft.surface_displacements(thin, grid, p)
