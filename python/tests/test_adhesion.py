"""adhesion= on solve_contact and solve_sweep against the coatfft program's files, and the
refusals."""
import json
import subprocess

import numpy as np
import pytest

import coatfft

# A rigid sphere on a soft half-space, Maugis' lambda = 1, approached and withdrawn.
SCENE = """[grid]
nx = 64
ny = 64
lx = 60e-6
ly = 60e-6
[substrate]
E = 0.91e9
nu = 0.3
[method]
name = "dcfft"
[contact]
indenter = "sphere"
radius = 1.0e-3
approach = [-0.05e-6, 0.0, 0.2e-6]
adhesion = "dugdale"
work_of_adhesion = 0.05
adhesion_range = 15.3e-9
unload = true
"""
LAW = dict(adhesion="dugdale", work_of_adhesion=0.05, adhesion_range=15.3e-9)


def operator_and_height():
    grid = coatfft.Grid(64, 64, 60e-6, 60e-6)
    return (coatfft.make_operator(grid, coatfft.Material(0.91e9, 0.3), method="dcfft"),
            coatfft.sphere_height(grid, 1e-3))


def test_adhesive_sweep_equals_the_program(tmp_path, coatfft_exe):
    (tmp_path / "adh.toml").write_text(SCENE)
    out = tmp_path / "out"
    subprocess.run([coatfft_exe, "run", str(tmp_path / "adh.toml"), "-o", str(out), "--quiet"],
                   check=True)
    op, h = operator_and_height()
    results = coatfft.solve_sweep(op, h, approaches=[0.2e-6, -0.05e-6, 0.0], unload=True, **LAW)
    assert [r.phase for r in results] == ["load", "load", "load", "unload", "unload"]
    assert all(r.converged for r in results)
    pressure = np.load(out / "pressure.npy")
    sigma0 = 0.05 / 15.3e-9
    summary = json.loads((out / "summary.json").read_text())
    for k, (r, row) in enumerate(zip(results, summary["sweep"])):
        np.testing.assert_allclose(r.pressure, pressure[k], rtol=0, atol=1e-12 * sigma0)
        assert r.load == pytest.approx(row["load"], rel=1e-12, abs=1e-18)
        assert r.cohesive_area == pytest.approx(row["cohesive_area"], rel=1e-12)
        assert r.pressure.min() >= -sigma0 * (1 + 1e-12)
    assert min(r.load for r in results) == pytest.approx(summary["adhesion"]["pull_off_load"],
                                                         rel=1e-12)


def test_an_adhesive_contact_pulls():
    op, h = operator_and_height()
    plain = coatfft.solve_contact(op, h, approach=0.1e-6)
    assert plain.cohesive_area is None and plain.jumped_off is None
    r = coatfft.solve_contact(op, h, approach=0.1e-6, **LAW)
    assert r.converged and r.cohesive_area > 0
    assert r.load < plain.load  # the cohesive zone pulls the sphere in


@pytest.mark.parametrize("bad", [dict(work_of_adhesion=0.0), dict(work_of_adhesion=-1.0),
                                 dict(adhesion_range=0.0), dict(adhesion_range=float("nan"))])
def test_a_bad_law_is_refused(bad):
    op, h = operator_and_height()
    with pytest.raises(ValueError, match="must be finite and > 0"):
        coatfft.solve_contact(op, h, approach=0.0, **{**LAW, **bad})


def test_keywords_without_adhesion_are_refused():
    op, h = operator_and_height()
    with pytest.raises(ValueError, match="need adhesion"):
        coatfft.solve_contact(op, h, approach=0.1e-6, work_of_adhesion=0.05)
    with pytest.raises(ValueError, match="dugdale"):
        coatfft.solve_contact(op, h, approach=0.1e-6, **{**LAW, "adhesion": "jkr"})
