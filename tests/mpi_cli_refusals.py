#!/usr/bin/python3
"""`coatfft run` under mpirun when ranks disagree (docs/scale.md): each case ends within seconds.

A rank that cannot read its scene (an MPMD launch giving each rank its own), a rank running
another command than rank 0's, ranks reading scenes of different grids, and a bad row of a height map read by rank 1 are refused on one line naming
the rank and what it read, exit status 2 and no output, where the refusing rank used to leave the
others waiting for ever. More ranks than grid rows (4 rows, 5 ranks: one rank holds none) give
the serial contact. A launch that hangs fails the test after 20 s. Usage: mpi_cli_refusals.py
COATFFT MPIEXEC
"""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

COATFFT, MPIEXEC = sys.argv[1], sys.argv[2]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def scene(ny, contact):
    return (f'[grid]\nnx = 16\nny = {ny}\nlx = 0.5e-3\nly = 0.4e-3\nboundary = "periodic"\n'
            f'[substrate]\nmaterial = "steel"\n[contact]\n{contact}')


def fail(message):
    print("FAILED:", message)
    sys.exit(1)


def run(ranks, scene_file, out):
    return ranks, ["run", str(scene_file), "-o", str(out), "--quiet"]


def launch(*commands):
    """mpirun of `ranks` ranks per (ranks, arguments), each its own program (MPMD)."""
    argv = [MPIEXEC, "--oversubscribe"]
    for ranks, args in commands:
        argv += [":"] * (len(argv) > 2) + ["-np", str(ranks), COATFFT, *args]
    try:
        return subprocess.run(argv, env=ENV, capture_output=True, text=True, timeout=20)
    except subprocess.TimeoutExpired:
        fail(f"{' '.join(argv)} still running after 20 s")


def refused(expect, out, *commands):
    r = launch(*commands)
    lines = [line for line in r.stderr.splitlines() if line.startswith("coatfft: error")]
    if r.returncode != 2 or len(lines) != 1 or any(e not in lines[0] for e in expect) or out.exists():
        fail(f"not refused with {expect}: exit {r.returncode}, {r.stderr!r}")
    print(f"refused: {lines[0]}")


def main():
    with tempfile.TemporaryDirectory() as name:
        tmp = Path(name)
        out = tmp / "out"
        sphere = 'indenter = "paraboloid"\nradius = 2e-3\nload = 0.05\n'
        (tmp / "a.toml").write_text(scene(16, sphere))
        refused(["rank 1: ", "missing.toml"], out, run(1, tmp / "a.toml", out),
                run(1, tmp / "missing.toml", out))
        refused(["rank 1: `surface`, where rank 0 runs `run`"], out, run(1, tmp / "a.toml", out),
                (1, ["surface", "-o", str(out / "z.npy"), "--nx", "16", "--ny", "16", "--lx",
                     "1e-3", "--ly", "1e-3", "--hurst", "0.8", "--rms-height", "1e-6"]))
        (tmp / "b.toml").write_text(scene(8, sphere))
        refused(["rank 1's scene", "b.toml", "16 x 8 cells", "rank 0's", "a.toml", "16 x 16 cells"],
                out, run(1, tmp / "a.toml", out), run(1, tmp / "b.toml", out))
        # Each rank's scene names its own height map (the same scene text in two folders): the
        # bad row is rank 1's, in its file.
        heights = np.zeros((16, 16))
        for folder, row in (("r0", None), ("r1", 12)):
            (tmp / folder).mkdir()
            h = heights.copy()
            if row is not None:
                h[row, 3] = np.nan
            np.save(tmp / folder / "h.npy", h)
            (tmp / folder / "s.toml").write_text(
                scene(16, 'indenter = "height_map"\npath = "h.npy"\nload = 0.05\n'))
        refused(["rank 1: ", str(tmp / "r1" / "h.npy"), "row 12, column 3"], out,
                run(1, tmp / "r0" / "s.toml", out), run(1, tmp / "r1" / "s.toml", out))
        # Four rows on five ranks against the serial run: a wavy surface in partial contact.
        y, x = np.mgrid[0:4, 0:16]
        np.save(tmp / "wavy.npy", 1e-7 * (2 - np.cos(2 * np.pi * x / 16) - np.cos(np.pi * y / 2)))
        (tmp / "rows.toml").write_text(
            scene(4, 'indenter = "height_map"\npath = "wavy.npy"\nload = 0.5\n'))
        serial = subprocess.run([COATFFT, "run", str(tmp / "rows.toml"), "-o", str(tmp / "serial"),
                                 "--quiet"], capture_output=True, text=True, timeout=20)
        r = launch(run(5, tmp / "rows.toml", tmp / "np5"))
        if serial.returncode or r.returncode:
            fail(f"4 rows on 5 ranks: exit {r.returncode}: {r.stderr} (serial {serial.stderr})")
        s, d = (json.loads((tmp / o / "summary.json").read_text()) for o in ("serial", "np5"))
        p_s, p_d = (np.load(tmp / o / "pressure.npy") for o in ("serial", "np5"))
        error = np.abs(p_s - p_d).max() / np.abs(p_s).max()
        if d["ranks"] != 5 or d["iterations"] != s["iterations"] or error > 1e-10:
            fail(f"4 rows on 5 ranks: {d['iterations']} iterations (serial {s['iterations']}), "
                 f"pressure within {error:.1e}")
        print(f"4 rows on 5 ranks: {d['iterations']} iterations as serially, pressure within "
              f"{error:.1e} of its largest value")
        print("mpi_cli_refusals: all checks passed")


main()
