#!/usr/bin/python3
"""`coatfft run` under mpirun (docs/scale.md) against the serial program.

A periodic rough TiN-coated contact (a height map read by rows) at 2 and 3 ranks (3: uneven
slabs), a paraboloid on it, a free Hertz contact on steel (DC-FFT) at 3 ranks, a free contact
on the coated body (frf-split) at 2 and 3 ranks, and the Hertz pressure on steel without [method]
(name = "auto", which chooses DC-FFT as serially) at 2 ranks: summary.json has
the serial run's keys and "ranks", the same iterations, and the load, approach, pressure,
displacement and gap equal the serial run's to 1e-10 (the grids are below the nested start's 128
cells a side; the nested start's equality is tests/test_distributed.cpp's); displacement.csv
holds the .npy files' values in the serial file's order. The rough contact and a pressure map
again with fields.nc (written by the ranks together): the serial file's format, variables,
coordinates and attributes, summary.json as its `summary`, the fields as above. A wisdom file is
written by rank 0 and read by the next run; one that does not hold wisdom is refused and left as
it is. Scenes that do not run distributed, and bad height maps, are refused on one line with exit
status 2 and no output. The lines a run prints on stdout (what it found) are the serial run's.
Usage: mpi_cli_run.py COATFFT MPIEXEC
"""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import netCDF4
import numpy as np

COATFFT, MPIEXEC = sys.argv[1], sys.argv[2]
SCENES = Path(__file__).resolve().parents[1] / "examples" / "scenes"
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

BODY = """
[substrate]
material = "steel"

[[coating]]
material = "titanium_nitride"
thickness = 1.0e-5
"""


# fields.nc instead of the .npy files (written by the ranks together under mpirun).
NETCDF = '[output]\nformat = "netcdf"\n'


def grid(nx, ny, boundary="periodic"):
    return f'[grid]\nnx = {nx}\nny = {ny}\nlx = 0.5e-3\nly = 0.4e-3\nboundary = "{boundary}"\n'


def run(args, ranks=None):
    command = [COATFFT, *args] if ranks is None else [MPIEXEC, "-np", str(ranks),
                                                       "--oversubscribe", COATFFT, *args]
    return subprocess.run(command, env=ENV, capture_output=True, text=True, timeout=120)


def fail(message):
    print("FAILED:", message)
    sys.exit(1)


def fields(folder, names):
    """The run's fields as (ny, nx) arrays: its .npy files, or fields.nc's variables over (x, y)."""
    if not (folder / "fields.nc").exists():
        return {field: np.load(folder / f"{field}.npy") for field in names}
    with netCDF4.Dataset(folder / "fields.nc") as nc:
        return {field: np.asarray(nc[field][:]).T for field in names}


def check_netcdf(name, serial, distributed):
    """fields.nc of the ranks against the serial one: the same format, dimensions, coordinates
    and attributes; its `summary` attribute is the run's summary.json."""
    with netCDF4.Dataset(serial / "fields.nc") as s, netCDF4.Dataset(distributed / "fields.nc") as d:
        if (s.data_model, d.data_model) != ("NETCDF3_64BIT_OFFSET",) * 2:
            fail(f"{name}: fields.nc is {d.data_model} (serial {s.data_model})")
        if list(s.variables) != list(d.variables) or s.dimensions.keys() != d.dimensions.keys():
            fail(f"{name}: fields.nc holds {list(d.variables)} (serial {list(s.variables)})")
        for v in s.variables:
            if s[v].dimensions != d[v].dimensions or s[v].__dict__ != d[v].__dict__:
                fail(f"{name}: fields.nc's {v} is not the serial file's")
        for axis in ("x", "y"):
            if np.any(s[axis][:] != d[axis][:]):
                fail(f"{name}: fields.nc's {axis} coordinates differ")
        if json.loads(d.summary) != json.loads((distributed / "summary.json").read_text()):
            fail(f"{name}: fields.nc's summary is not summary.json")


def check_equal(name, serial, distributed, ranks):
    s, d = json.loads((serial / "summary.json").read_text()), json.loads(
        (distributed / "summary.json").read_text())
    if d["ranks"] != ranks or s["ranks"] != 1:
        fail(f"{name}: ranks {d['ranks']} (serial {s['ranks']})")
    if missing := set(s) - set(d):
        fail(f"{name}: summary.json lacks the serial keys {sorted(missing)}")
    contact = "iterations" in s
    if contact:
        check_contact_numbers(name, s, d)
    else:
        check_load_reports(name, s, d)
    names = ("pressure", "uz", "gap") if contact else ("pressure", "uz")
    if (serial / "fields.nc").exists():
        check_netcdf(name, serial, distributed)
    s_fields, d_fields = fields(serial, names), fields(distributed, names)
    largest = 0.0
    for field in names:
        a, b = s_fields[field], d_fields[field]
        error = np.abs(a - b).max() / np.abs(a).max()
        if a.shape != b.shape or error > 1e-10:
            fail(f"{name} at {ranks} ranks: {field} differs by {error:.2e} of its largest value")
        largest = max(largest, error)
    what = f"{d['iterations']} iterations (serial {s['iterations']})" if contact else "known load"
    print(f"{name} at {ranks} ranks: {what}, fields within {largest:.1e} of their largest values")
    csv = np.loadtxt(distributed / "displacement.csv", delimiter=",", skiprows=1)
    serial_csv = np.loadtxt(serial / "displacement.csv", delimiter=",", skiprows=1)
    if csv.shape != serial_csv.shape or np.any(csv[:, :2] != serial_csv[:, :2]):
        fail(f"{name}: displacement.csv's cells are not the serial file's")
    if np.any(csv[:, 2] != d_fields["pressure"].ravel()) or np.any(
            csv[:, 3] != d_fields["uz"].ravel()):
        fail(f"{name}: displacement.csv's values are not those of the pressure and uz files")


def check_contact_numbers(name, s, d):
    if d["iterations"] != s["iterations"]:
        fail(f"{name}: {d['iterations']} iterations, serially {s['iterations']}")
    if not d["converged"] or abs(d["load"] - s["load"]) > 1e-12 * s["load"]:
        fail(f"{name}: load {d['load']} against {s['load']}, converged {d['converged']}")
    if abs(d["approach"] - s["approach"]) > 1e-10 * abs(s["approach"]):
        fail(f"{name}: approach {d['approach']} against {s['approach']}")


# A known load's reports, each gathered over the ranks: the a-posteriori error (the centre cell's
# displacement and max |u|), the load's discretisation estimate (its displacement over the ranks'
# rows, the 2 x 2 blocks across their borders), the error against Hertz's closed form.
def check_load_reports(name, s, d):
    numbers = [("total_load",), ("uz_center",), ("uz_max",), ("a_posteriori", "error"),
               ("load_discretization", "estimated_error"),
               ("load_discretization", "absolute_error"), ("max_error_vs_hertz",)]
    for keys in numbers:
        a, b = s, d
        for key in keys:
            a, b = (a or {}).get(key), (b or {}).get(key)
        if (a is None) != (b is None) or (a is not None and abs(a - b) > 1e-10 * abs(a)):
            fail(f"{name}: {'.'.join(keys)} {b} against {a} serially")


def refused(tmp, expect, scene_text):
    scene = tmp / "refused.toml"
    scene.write_text(scene_text)
    out = tmp / "refused_out"
    r = run(["run", str(scene), "-o", str(out)], ranks=2)
    lines = [line for line in r.stderr.splitlines() if line.startswith("coatfft: error")]
    if r.returncode != 2 or len(lines) != 1 or expect not in lines[0] or out.exists():
        fail(f"not refused with \"{expect}\": exit {r.returncode}, {r.stderr!r}")


def check_auto_choice(tmp):
    """The homogeneous Hertz scene without [method] at 2 ranks: "auto" chose dcfft, as serially,
    with the serial run's report of the choice."""
    s, d = (json.loads((tmp / f"hertz_auto_{o}" / "summary.json").read_text())
            for o in ("serial", "np2"))
    if (d["method_requested"], d["method"]) != ("auto", "dcfft") or d["method"] != s["method"]:
        fail(f"hertz_auto: {d['method_requested']} chose {d['method']} (serial {s['method']})")
    if d["auto"]["method"] != s["auto"]["method"]:
        fail(f"hertz_auto: the choice's report {d['auto']['method']} (serial {s['auto']['method']})")
    print(f"hertz_auto at 2 ranks: \"auto\" chose {d['method']}, as serially")


def check_topography_by_gap(tmp, heights, nx, ny):
    """A measured topography, refused under mpirun: its gap from `coatfft topography --gap` as a
    height map at 3 ranks gives the serial topography scene's contact (tilted, detrended)."""
    y, x = np.mgrid[0:ny, 0:nx]
    np.save(tmp / "z_tilted.npy", heights + 2e-9 * x - 1e-9 * y)
    base = grid(nx, ny) + BODY + "[contact]\nload = 4.0\n"
    scene = tmp / "topography.toml"
    scene.write_text(base + 'topography = "z_tilted.npy"\ndetrend = "plane"\n')
    if (r := run(["run", str(scene), "-o", str(tmp / "topography_serial"), "--quiet"])).returncode:
        fail(r.stderr)
    if (r := run(["topography", str(tmp / "z_tilted.npy"), "--detrend", "plane", "--gap", "-o",
                  str(tmp / "h_tilted.npy")])).returncode:
        fail(r.stderr)
    refused(tmp, "--gap -o h.npy` writes its gap", scene.read_text())
    scene.write_text(base + 'indenter = "height_map"\npath = "h_tilted.npy"\n')
    if (r := run(["run", str(scene), "-o", str(tmp / "topography_np3")], 3)).returncode:
        fail(f"topography's gap at 3 ranks: {r.stderr}")
    s, d = (json.loads((tmp / f"topography_{o}" / "summary.json").read_text())
            for o in ("serial", "np3"))
    if d["iterations"] != s["iterations"]:
        fail(f"topography's gap: {d['iterations']} iterations (serial {s['iterations']})")
    largest = 0.0
    for field in ("pressure", "uz", "gap"):
        a, b = (np.load(tmp / f"topography_{o}" / f"{field}.npy") for o in ("serial", "np3"))
        largest = max(largest, np.abs(a - b).max() / np.abs(a).max())
    if largest > 1e-10:
        fail(f"topography's gap at 3 ranks: fields differ by {largest:.2e}")
    print(f"topography's gap at 3 ranks: {d['iterations']} iterations (serial {s['iterations']}), "
          f"fields within {largest:.1e} of their largest values")


def main():
    with tempfile.TemporaryDirectory() as name:
        tmp = Path(name)
        nx, ny = 64, 50
        z = tmp / "z.npy"
        r = run(["surface", "-o", str(z), "--nx", str(nx), "--ny", str(ny), "--lx", "0.5e-3",
                 "--ly", "0.4e-3", "--hurst", "0.8", "--rms-height", "0.2e-6", "--seed", "7"])
        if r.returncode != 0:
            fail(r.stderr)
        heights = np.load(z)
        np.save(tmp / "gap.npy", heights.max() - heights)
        rough = grid(nx, ny) + BODY + '[contact]\nindenter = "height_map"\npath = "gap.npy"\nload = 4.0\n'
        sphere = grid(nx, ny) + BODY + '[contact]\nindenter = "paraboloid"\nradius = 2e-3\nload = 2.0\n'
        hertz = (grid(nx, ny, "free") + '[substrate]\nmaterial = "steel"\n[method]\nname = "dcfft"\n'
                 '[contact]\nindenter = "paraboloid"\nradius = 5e-3\nload = 0.5\n')
        coated_free = (grid(nx, ny, "free") + BODY + '[method]\nname = "frf-split"\n'
                       '[contact]\nindenter = "paraboloid"\nradius = 2e-3\nload = 20.0\n')
        # The same map as big-endian float32: each rank converts its rows as the serial reader does.
        np.save(tmp / "gap32.npy", (heights.max() - heights).astype(">f4"))
        rough32 = rough.replace("gap.npy", "gap32.npy")
        # Known loads: the bundled examples (Hertz on steel by dcfft; on TiN-coated steel by
        # frf-split, cell averages on 97 rows: at 3 ranks the second starts on row 33, whose 2 x 2
        # blocks pair it with the first rank's last), and a pressure map read by rows.
        hertz_example = (SCENES / "hertz.toml").read_text()
        # Without [method]: "auto", whose choice on a homogeneous body needs no reference.
        hertz_auto = hertz_example[:hertz_example.index("[method]")]
        coated_example = (SCENES / "coated_hertz.toml").read_text()
        np.save(tmp / "p.npy", 1e8 * (heights - heights.min()))
        pressure_map = grid(nx, ny) + BODY + '[pressure]\nkind = "file"\npath = "p.npy"\n'
        for name, text, rank_counts in (("rough", rough, (2, 3)), ("paraboloid", sphere, (3,)),
                                        ("hertz", hertz, (3,)), ("rough_float32", rough32, (3,)),
                                        ("coated_free", coated_free, (2, 3)),
                                        ("hertz_example", hertz_example, (3,)),
                                        ("hertz_auto", hertz_auto, (2,)),
                                        ("coated_hertz_example", coated_example, (2, 3)),
                                        ("pressure_map", pressure_map, (3,)),
                                        ("rough_netcdf", rough + NETCDF, (3,)),
                                        ("pressure_map_netcdf", pressure_map + NETCDF, (2,))):
            scene = tmp / f"{name}.toml"
            scene.write_text(text)
            if (serial := run(["run", str(scene), "-o", str(tmp / f"{name}_serial")])).returncode:
                fail(serial.stderr)
            for ranks in rank_counts:
                out = tmp / f"{name}_np{ranks}"
                if (r := run(["run", str(scene), "-o", str(out)], ranks)).returncode:
                    fail(f"{name} at {ranks} ranks: {r.stderr}")
                check_equal(name, tmp / f"{name}_serial", out, ranks)
                # What the run found (a contact's radius and peak pressure), printed once.
                if r.stdout != serial.stdout:
                    fail(f"{name} at {ranks} ranks printed {r.stdout!r}, serially {serial.stdout!r}")

        check_auto_choice(tmp)
        check_topography_by_gap(tmp, heights, nx, ny)

        # A wisdom file: written by rank 0 with every rank's plans, read again by the next run.
        wisdom = tmp / "plans.wisdom"
        scene = tmp / "wisdom.toml"
        scene.write_text(rough.replace("[contact]", f'[method]\nwisdom = "{wisdom}"\n[contact]'))
        for attempt in (1, 2):
            if (r := run(["run", str(scene), "-o", str(tmp / "wisdom_out")], 2)).returncode:
                fail(f"wisdom run {attempt}: {r.stderr}")
            if not wisdom.read_text().startswith("(fftw-3"):
                fail(f"wisdom run {attempt}: {wisdom} holds no FFTW wisdom")
        wisdom.write_text("not wisdom")
        refused(tmp, "does not hold FFTW wisdom", scene.read_text())
        if wisdom.read_text() != "not wisdom":
            fail("a file that is not wisdom was overwritten")
        refused(tmp, "uses Love's coefficients of a homogeneous half-space",
                coated_free.replace('name = "frf-split"', 'name = "dcfft"'))
        refused(tmp, 'name = "frf-dcfft" on a free boundary',
                coated_free.replace('name = "frf-split"', 'name = "frf-dcfft"'))
        refused(tmp, '[method] name = "auto" on a free boundary of a coated body',
                coated_free.replace('name = "frf-split"', 'name = "auto"'))
        refused(tmp, "the contact reaches the domain edge", hertz.replace("load = 0.5", "load = 500.0"))
        np.savetxt(tmp / "p.csv", 1e8 * (heights - heights.min()), delimiter=",")
        refused(tmp, "[pressure] path", pressure_map.replace("p.npy", "p.csv"))
        refused(tmp, "[shear] does not run distributed yet",
                (SCENES / "coated_hertz_shear.toml").read_text())
        refused(tmp, "[contact] friction", rough + "friction = 0.3\n")
        refused(tmp, "[contact] hardness", rough + "hardness = 1e9\n")
        refused(tmp, "[contact] adhesion", rough + 'adhesion = "dugdale"\nwork_of_adhesion = 0.05\n'
                'adhesion_range = 1e-8\n')
        bad = heights.max() - heights
        bad[37, 5] = np.nan
        np.save(tmp / "gap.npy", bad)
        refused(tmp, "gap.npy: row 37, column 5: height nan is not finite", rough)
        np.save(tmp / "gap_f.npy", np.asfortranarray(heights.max() - heights))
        refused(tmp, "fortran_order is True", rough.replace("gap.npy", "gap_f.npy"))
        np.savetxt(tmp / "gap.csv", bad, delimiter=",")
        refused(tmp, "reads a height map from .npy only", rough.replace("gap.npy", "gap.csv"))
        print("mpi_cli_run: all checks passed")


main()
