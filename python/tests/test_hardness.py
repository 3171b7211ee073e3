"""hardness= on solve_contact and solve_sweep (unload=) against the coatfft program's files, and
the refusals."""
import json
import subprocess

import numpy as np
import pytest

import coatfft

# A rigid sphere on steel under 2 um of TiN, capped at 2.5 GPa, loaded and unloaded.
SCENE = """[grid]
nx = 32
ny = 32
lx = 80e-6
ly = 80e-6
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 2.0e-6
interface = "bonded"
[method]
name = "frf-split"
[contact]
indenter = "sphere"
radius = 1.0e-3
load = [0.5, 1.0, 2.0]
hardness = 2.5e9
unload = true
"""


def operator_and_height():
    grid = coatfft.Grid(32, 32, 80e-6, 80e-6)
    body = coatfft.LayerStack(coatfft.material("steel"),
                              [coatfft.Coating(coatfft.material("titanium_nitride"), 2e-6)])
    return coatfft.make_operator(grid, body, method="frf-split"), coatfft.sphere_height(grid, 1e-3)


def test_unloading_sweep_equals_the_program(tmp_path, coatfft_exe):
    (tmp_path / "cap.toml").write_text(SCENE)
    out = tmp_path / "out"
    subprocess.run([coatfft_exe, "run", str(tmp_path / "cap.toml"), "-o", str(out), "--quiet"],
                   check=True)
    op, h = operator_and_height()
    results = coatfft.solve_sweep(op, h, loads=[2.0, 0.5, 1.0], hardness=2.5e9, unload=True)
    assert [r.phase for r in results] == ["load", "load", "load", "unload", "unload"]
    assert all(r.converged for r in results)
    plastic = np.load(out / "plastic.npy")
    pressure = np.load(out / "pressure.npy")
    for k, r in enumerate(results):
        np.testing.assert_allclose(r.pressure, pressure[k], rtol=0, atol=1e-12 * 2.5e9)
        np.testing.assert_allclose(r.plastic_depth, plastic[k], rtol=0,
                                   atol=1e-12 * plastic.max())
    summary = json.loads((out / "summary.json").read_text())
    for key, value in summary["plastic"].items():
        assert results[-1].plastic[key] == pytest.approx(value, rel=1e-9, abs=1e-30), key
    for row, r in zip(summary["sweep"], results):
        assert row["phase"] == r.phase
        assert row["plastic_area"] == pytest.approx(r.plastic["plastic_area"], rel=1e-12)
    residual = coatfft.residual_gap(h, results[-1].plastic_depth)
    np.testing.assert_allclose(residual, np.load(out / "residual_gap.npy"), rtol=0,
                               atol=1e-12 * residual.max())
    # run_scene gives the same fields, as the program's files.
    run = coatfft.run_scene(str(tmp_path / "cap.toml"))
    assert run["plastic"].shape == (5, 32, 32)
    np.testing.assert_allclose(run["residual_gap"], residual, rtol=0, atol=1e-12 * residual.max())


def test_a_capped_solve_flows_at_the_hardness():
    op, h = operator_and_height()
    elastic = coatfft.solve_contact(op, h, load=2.0)
    assert elastic.plastic is None and elastic.plastic_depth is None and elastic.phase is None
    r = coatfft.solve_contact(op, h, load=2.0, hardness=2.5e9)
    assert r.converged and r.max_pressure == 2.5e9 < elastic.max_pressure
    at_cap = r.pressure == 2.5e9
    assert at_cap.any()
    np.testing.assert_array_equal(r.plastic_depth[~at_cap], 0.0)
    np.testing.assert_array_equal(r.plastic_depth[at_cap], -r.gap[at_cap])
    cell = (80e-6 / 32) ** 2
    assert r.plastic["plastic_area"] == pytest.approx(at_cap.sum() * cell, rel=1e-12)


@pytest.mark.parametrize("bad", [0.0, -1e9, float("nan"), float("inf")])
def test_a_bad_hardness_is_refused(bad):
    op, h = operator_and_height()
    with pytest.raises(ValueError, match="hardness"):
        coatfft.solve_contact(op, h, load=2.0, hardness=bad)


def test_unload_needs_a_hardness():
    op, h = operator_and_height()
    with pytest.raises(ValueError, match="unload=True needs hardness"):
        coatfft.solve_sweep(op, h, loads=[1.0, 2.0], unload=True)
