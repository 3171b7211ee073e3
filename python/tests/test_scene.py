"""run_scene against `coatfft run`, the operators of make_operator against the program's, and
validate_frf against `coatfft validate-frf` (their errors: test_errors.py)."""
import json
import os
import re
import subprocess
import warnings

import numpy as np
import pytest

import coatfft
from conftest import SCENES, rel_max


def steel():
    return coatfft.material("steel")


def tin_on_steel(thickness):
    tin = coatfft.Coating(coatfft.material("titanium_nitride"), thickness)
    return coatfft.LayerStack(steel(), [tin])


def example_table():
    k, h = np.loadtxt(SCENES / "tabulated_frf.csv", delimiter=",", skiprows=1, unpack=True)
    return coatfft.TabulatedFrf(k, h)


# Each scene with its body as the scene file states it, for make_operator.
BODIES = {
    "coated_hertz": lambda: tin_on_steel(1e-4),
    "tin_2um": lambda: tin_on_steel(2e-6),
    "auto_tolerance": lambda: tin_on_steel(20e-6),
    "hertz": steel,
    "sphere_contact": steel,
    "rough_sphere_contact": steel,
    "tabulated_frf": example_table,
}


@pytest.fixture(scope="module")
def runs(coatfft_exe, tmp_path_factory):
    """Each scene run once by the program and once by run_scene."""
    results = {}
    for name in BODIES:
        out = tmp_path_factory.mktemp(name)
        scene = SCENES / f"{name}.toml"
        done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(out), "--quiet"],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        results[name] = (out, coatfft.run_scene(str(scene)))
    return results


def without_timings(value):
    """summary.json less what differs between two runs: the keys ending in _seconds, and the
    times auto's "why" quotes ("0.0136 s setup + 1 x 0.000252 s")."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if not k.endswith("_seconds")}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    if isinstance(value, str):
        return re.sub(r"[0-9.e+-]+ s\b", "<t> s", value)
    return value


@pytest.mark.parametrize("name", list(BODIES))
def test_run_scene_equals_the_program(runs, name):
    out, python = runs[name]
    contact = "contact" in (SCENES / f"{name}.toml").read_text()
    fields = ["uz", "pressure"] + (["gap"] if contact else [])
    assert sorted(python) == sorted(fields + ["summary"])
    for field in fields:
        cli = np.load(out / f"{field}.npy")
        ours = python[field]
        assert ours.dtype == cli.dtype == np.float64 and ours.shape == cli.shape
        assert ours.flags.c_contiguous and ours.flags.writeable
        # The same computation in the same library: measured max difference exactly 0 for every
        # field of every scene; the bound is the brief's 1e-14 of max |field|.
        scale = np.abs(cli).max()
        assert np.abs(ours - cli).max() <= 1e-14 * scale
    summary = json.loads((out / "summary.json").read_text())
    assert without_timings(python["summary"]) == without_timings(summary)
    assert set(python["summary"]) == set(summary)  # the timings too are there


@pytest.mark.parametrize("name", list(BODIES))
def test_make_operator_as_the_program_built_it(runs, name):
    out, _ = runs[name]
    summary = json.loads((out / "summary.json").read_text())
    grid = coatfft.Grid(summary["nx"], summary["ny"], summary["lx"], summary["ly"])
    if summary["method_requested"] == "auto":
        # What auto was asked (tolerance, the applications of a contact solve, the reference
        # loads when the scene has one; else the grid's own, as make_operator's default).
        auto = summary["auto"]
        options = {"tolerance": auto["tolerance"], "applications": auto["applications"]}
        if len(auto["reference_loads"]) == 1:
            options["load_radius"] = auto["reference_loads"][0]["radius"]
    else:
        options = {"method": summary["method"]}
        options.update({k: summary[k] for k in ("alpha",) if k in summary})
    op = coatfft.make_operator(grid, BODIES[name](), **options)
    assert op.method == summary["method"]
    if "auto" in summary:
        # The same choice for the same reasons; only the predicted times differ (the program
        # pays FFTW's first plan of a process, docs/auto.md), in the keys *_seconds and in "why".
        assert without_timings(op.report["auto"]) == without_timings(summary["auto"])
    for key in ("frf", "split_beta", "fft_nx", "fft_ny", "g0", "g0_method"):
        if key in summary:
            assert op.report[key] == summary[key]
    # The program's displacement from its own pressure: for a contact, the converged pressure.
    # The same operator: measured difference 0; 1e-14 of max |u| is round-off.
    pressure = np.load(out / "pressure.npy")
    uz = np.load(out / "uz.npy")
    assert rel_max(op.apply(pressure), uz) <= 1e-14


def test_contact_not_converged_warns_as_the_program(coatfft_exe, tmp_path):
    # Two iterations are not enough: the program writes its files, says so on stderr and exits
    # with status 3; run_scene returns the same fields, and the summary says so (docs/python.md:
    # run_scene prints no warnings, neither does it raise).
    scene = tmp_path / "short.toml"
    scene.write_text((SCENES / "sphere_contact.toml").read_text().replace(
        "max_iterations = 1000", "max_iterations = 2"))
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(tmp_path / "out"),
                           "--quiet"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 3 and "did not converge" in done.stderr
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        python = coatfft.run_scene(scene)
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert without_timings(python["summary"]) == without_timings(summary)
    assert summary["status"] == "iteration_limit" and not summary["converged"]
    assert summary["warnings"] == ["not converged after 2 iterations (residual "
                                   f"{summary['residual']}, tolerance 1e-10)"]
    for field in ("uz", "pressure", "gap"):
        np.testing.assert_array_equal(python[field], np.load(tmp_path / "out" / f"{field}.npy"))


def snapshot(folder):
    return {e.name: (e.stat().st_size, e.stat().st_mtime_ns) for e in os.scandir(folder)}


def test_run_scene_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    before = snapshot(SCENES)
    for name in ("coated_hertz", "sphere_contact"):
        coatfft.run_scene(str(SCENES / f"{name}.toml"))
    assert snapshot(SCENES) == before
    assert list(tmp_path.iterdir()) == []


def test_run_scene_reads_but_never_writes_wisdom(coatfft_exe, tmp_path, monkeypatch):
    # A scene naming an FFTW wisdom file: the program saves it, run_scene only reads it.
    text = (SCENES / "hertz.toml").read_text().replace(
        'name = "dcfft"', 'name = "dcfft"\nwisdom = "plans.wisdom"')
    scene = tmp_path / "scene.toml"
    scene.write_text(text)
    monkeypatch.chdir(tmp_path)
    python = coatfft.run_scene(str(scene))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(tmp_path / "out"), "--quiet"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "plans.wisdom").is_file()
    # Its wisdom there, run_scene reads it and computes the same field (round-off at most).
    again = coatfft.run_scene(str(scene))
    assert rel_max(again["uz"], python["uz"]) <= 1e-14
    assert (tmp_path / "plans.wisdom").read_bytes().startswith(b"(fftw-3")


CHECKS = ["c0", "c_inf", "frf_at_points", "frf_between_points", "hertz_frf_split",
          "hertz_hankel", "uniform_disk_frf_split", "uniform_disk_hankel"]
GRID = coatfft.Grid(64, 64, 0.6e-3, 0.6e-3)


def test_validate_frf_passes_the_built_in_frf():
    stack = tin_on_steel(2e-6)
    result = coatfft.validate_frf(stack, stack, GRID)
    assert result["passed"] is True
    assert result["reference"] == "coatfft's coated_bonded FRF of the stack"
    assert [c["name"] for c in result["checks"]] == CHECKS
    for check in result["checks"]:
        # The same FRF against itself: measured difference 0 in every check.
        assert check["passed"] and check["difference"] <= 1e-10
        assert check["tolerance"] == 1e-6 and check["detail"] and check["reference"]
    half_space = coatfft.validate_frf(steel(), steel(), GRID, tolerance=1e-8)
    assert half_space["passed"] and half_space["reference"].startswith("Boussinesq")
    # A tolerance below what the references resolve is raised to their floors.
    floors = {c["name"]: c["tolerance"] for c in coatfft.validate_frf(
        stack, stack, GRID, tolerance=1e-13)["checks"]}
    assert floors["hertz_frf_split"] == 1e-10 and floors["hertz_hankel"] == 1e-9
    assert floors["c0"] == 1e-13


def test_validate_frf_fails_an_frf_off_by_1e_3():
    stack = tin_on_steel(2e-6)
    c0, c_inf = 2 / stack.substrate.E_star, 2 / stack.coatings[0].material.E_star
    off = 1 + 1e-3  # H, c0 and c_inf 0.1 % too large: a consistent FRF of another body
    user = coatfft.UserFrf(lambda k: off * coatfft.frf(stack, k), off * c0, off * c_inf)
    result = coatfft.validate_frf(user, stack, GRID)
    assert result["passed"] is False
    for check in result["checks"]:
        # Every check sees the 1e-3 (measured within 4e-16 of it; the Hankel integrals and the
        # split kernel to their tolerances 1e-10, so 1e-6 relative of 1e-3).
        assert not check["passed"], check["name"]
        assert check["difference"] == pytest.approx(1e-3, rel=1e-6), check["name"]


def test_validate_frf_reports_an_frf_inconsistent_with_its_limits():
    stack = tin_on_steel(2e-6)
    c0, c_inf = 2 / stack.substrate.E_star, 2 / stack.coatings[0].material.E_star
    user = coatfft.UserFrf(lambda k: (1 + 1e-3) * coatfft.frf(stack, k), c0, c_inf)
    result = coatfft.validate_frf(user, stack, GRID)
    failed = {c["name"] for c in result["checks"] if not c["passed"]}
    # k H tends to (1 + 1e-3) c_inf: the Hankel integrals of this FRF do not converge, which
    # fails their checks (with the reason in the detail) instead of aborting the validation.
    assert not result["passed"] and {"frf_at_points", "hertz_hankel"} <= failed
    hankel = next(c for c in result["checks"] if c["name"] == "hertz_hankel")
    assert "the integral of the FRF failed" in hankel["detail"]


@pytest.mark.parametrize("with_load", [False, True])
def test_validate_frf_equals_the_program(coatfft_exe, tmp_path, with_load):
    # The table of examples/scenes/tabulated_frf.toml, checked by `coatfft validate-frf` and by
    # validate_frf on the scene's grid against the body its [substrate] and [[coating]] claim.
    # The program replaces the Hertz check load by the scene's [pressure] (p0 = 1 GPa, a = 1 mm,
    # cell averages), which validate_frf takes as keywords; without a [pressure] (a [contact]
    # instead) both use the default loads.
    text = (SCENES / "tabulated_frf.toml").read_text()
    text = text.replace('path = "tabulated_frf.csv"',
                        f'path = "{(SCENES / "tabulated_frf.csv").as_posix()}"')
    if not with_load:
        text = text[:text.index("[pressure]")] + text[text.index("[method]"):]
        text += '\n[contact]\nindenter = "sphere"\nradius = 0.01\nload = 1.0\n'
    scene = tmp_path / "table.toml"
    scene.write_text(text)
    done = subprocess.run([coatfft_exe, "validate-frf", str(scene)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    load = dict(load="hertz", amplitude=1e9, load_radius=1e-3,
                sampling="cell_average") if with_load else {}
    result = coatfft.validate_frf(example_table(), tin_on_steel(1e-4),
                                  coatfft.Grid(97, 97, 4e-3, 4e-3), **load)
    assert result["passed"]
    rows = {}
    for line in done.stdout.splitlines():
        match = re.match(r"(\w+)\s+(\S+)\s+(.*?)\s+(\S+)\s+(ok|FAILED)\s+(.*)$", line)
        if match and match.group(1) in CHECKS:
            rows[match.group(1)] = match.groups()[1:]
    assert list(rows) == CHECKS
    for check in result["checks"]:
        difference, detail, tolerance, verdict, reference = rows[check["name"]]
        # The program prints 3 digits ("2.52e-09"): the same number to 5e-3 relative.
        assert check["difference"] == pytest.approx(float(difference), rel=5e-3, abs=1e-300)
        assert float(tolerance) == check["tolerance"] and verdict == "ok"
        assert reference == check["reference"]
        # The program appends "(estimated)" or "(given)" to a table's limits.
        assert detail.startswith(check["detail"])


def test_run_scene_of_a_sweep_equals_the_program(coatfft_exe, tmp_path):
    # [contact] load as a list: the fields stacked one per value (ascending), as the program's
    # .npy files, and the sweep's rows in the summary.
    scene = tmp_path / "sweep.toml"
    scene.write_text('[grid]\nnx = 32\nny = 32\nlx = 3.0e-3\nly = 3.0e-3\nboundary = "periodic"\n'
                     '[substrate]\nmaterial = "steel"\n'
                     '[contact]\nindenter = "paraboloid"\nradius = 0.01\nload = [20.0, 10.0]\n')
    out = tmp_path / "out"
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(out), "--quiet"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    run = coatfft.run_scene(str(scene))
    for name in ("pressure", "uz", "gap"):
        assert run[name].shape == (2, 32, 32)
        np.testing.assert_array_equal(run[name], np.load(out / f"{name}.npy"))
    assert [row["load"] for row in run["summary"]["sweep"]] == pytest.approx([10.0, 20.0])
