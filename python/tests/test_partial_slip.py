"""solve_partial_slip against the coatfft program's files, and its refusals."""
import json
import subprocess

import numpy as np
import pytest

import coatfft

# A rigid sphere on a nearly incompressible half-space (a/dx = 8), a fretting path in the order
# given.
SCENE = """[grid]
nx = 41
ny = 41
lx = 1.9902e-3
ly = 1.9902e-3
[substrate]
E = 2e9
nu = 0.4999
[method]
name = "dcfft"
[contact]
indenter = "sphere"
radius = 0.01
load = 20.0
friction = 0.3
tangential_load = [1.5, 3.0, 0.0, -3.0, 0.0, 3.0]
"""


def test_partial_slip_equals_the_program(tmp_path, coatfft_exe):
    (tmp_path / "slip.toml").write_text(SCENE)
    out = tmp_path / "out"
    subprocess.run([coatfft_exe, "run", str(tmp_path / "slip.toml"), "-o", str(out), "--quiet"],
                   check=True)
    grid = coatfft.Grid(41, 41, 1.9902e-3, 1.9902e-3)
    body = coatfft.Material(2e9, 0.4999)
    op = coatfft.make_operator(grid, body, method="dcfft")
    h = coatfft.sphere_height(grid, 0.01)
    r = coatfft.solve_partial_slip(op, h, body, friction=0.3,
                                   tangential_load=[1.5, 3.0, 0.0, -3.0, 0.0, 3.0], load=20.0)
    assert r.converged and r.warning == ""
    for name in ("shear_x", "shear_y", "slip_x", "slip_y"):
        field = np.load(out / f"{name}.npy")
        assert field.shape == (6, 41, 41)
        np.testing.assert_allclose(getattr(r, name), field, rtol=0,
                                   atol=1e-12 * np.abs(field).max())
    stick = np.load(out / "stick.npy")
    assert stick.dtype == np.uint8 and r.stick.dtype == np.uint8
    np.testing.assert_array_equal(r.stick, stick)
    summary = json.loads((out / "summary.json").read_text())
    assert r.summary.keys() == summary["partial_slip"].keys()
    for key, value in summary["partial_slip"].items():
        assert r.summary[key] == pytest.approx(value, rel=1e-9), key
    assert r.fretting["loops"] == pytest.approx(summary["fretting"]["loops"])
    assert [row["step"] for row in r.fretting["steps"]] == [1, 2, 3, 4, 5, 6]
    # run_scene gives the same fields, as the program's files.
    run = coatfft.run_scene(str(tmp_path / "slip.toml"))
    np.testing.assert_array_equal(run["stick"], stick)
    np.testing.assert_allclose(run["shear_x"], r.shear_x, rtol=0,
                               atol=1e-12 * np.abs(r.shear_x).max())
    # One value: the fields of one step, (ny, nx).
    one = coatfft.solve_partial_slip(op, h, body, friction=0.3, tangential_load=3.0, load=20.0)
    assert one.shear_x.shape == (41, 41) and one.fretting is None
    assert one.shear_x.sum() * grid.dx * grid.dy == pytest.approx(3.0, rel=1e-7)


def test_partial_slip_errors():
    grid = coatfft.Grid(41, 41, 1.9902e-3, 1.9902e-3)
    body = coatfft.Material(2e9, 0.4999)
    op = coatfft.make_operator(grid, body, method="dcfft")
    h = coatfft.sphere_height(grid, 0.01)
    with pytest.raises(ValueError, match="exactly one of load"):
        coatfft.solve_partial_slip(op, h, body, friction=0.3, tangential_load=1.0)
    with pytest.raises(ValueError, match="exactly one of tangential_load"):
        coatfft.solve_partial_slip(op, h, body, friction=0.3, load=20.0)
    with pytest.raises(ValueError, match="friction"):
        coatfft.solve_partial_slip(op, h, body, friction=0.0, tangential_load=1.0, load=20.0)
    with pytest.raises(ValueError, match="full sliding"):
        coatfft.solve_partial_slip(op, h, body, friction=0.3, tangential_load=6.0, load=20.0)
    with pytest.raises(ValueError, match="empty path"):
        coatfft.solve_partial_slip(op, h, body, friction=0.3, tangential_load=[], load=20.0)
    with pytest.raises(ValueError, match="not the body"):
        coatfft.solve_partial_slip(op, h, coatfft.material("steel"), friction=0.3,
                                   tangential_load=1.0, load=20.0)
