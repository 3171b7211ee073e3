#!/usr/bin/python3
"""Peak memory of `coatfft run` against the estimate it checks before starting.

For a few scenes (each method, a known pressure and a contact), runs the coatfft program under
bench_peak_rss (the child's own peak resident set, wait4) and reads summary.json's
estimated_memory_bytes. Writes bench/results/memory_estimate.csv and prints a Markdown table.
The estimate is meant as an upper bound of the dominant arrays: the ratio measured/estimate
should stay below 1 once the fixed cost of the program (about 10-20 MiB) is negligible.

Usage: scripts/memory_estimate_check.py [BUILD_DIR]   (default: build)
"""
import csv
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BUILD = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "build").resolve()

BODY = {"homogeneous": '[substrate]\nmaterial = "steel"\n',
        "coated": '[substrate]\nmaterial = "steel"\n[[coating]]\nmaterial = "titanium_nitride"\n'
                  'thickness = 20e-6\n'}
PRESSURE = '[pressure]\nkind = "hertz"\np0 = 1e9\na = 0.5e-3\n'
CONTACT = '[contact]\nindenter = "paraboloid"\nradius = 0.01\nload = 50.0\n'

CASES = [  # name, n, body, load, method lines
    ("dcfft pressure", 1024, "homogeneous", PRESSURE, 'name = "dcfft"'),
    ("dcfft pressure", 2048, "homogeneous", PRESSURE, 'name = "dcfft"'),
    ("frf-split pressure", 1024, "coated", PRESSURE, 'name = "frf-split"'),
    ("frf-dcfft pressure", 1024, "coated", PRESSURE, 'name = "frf-dcfft"\nalpha = 2'),
    ("frf-spectral pressure", 1024, "coated", PRESSURE, 'name = "frf-spectral"\nalpha = 4'),
    ("dcfft contact", 1024, "homogeneous", CONTACT, 'name = "dcfft"'),
    ("frf-split contact", 1024, "coated", CONTACT, 'name = "frf-split"'),
]


def run_case(tmp, name, n, body, load, method):
    scene = tmp / "scene.toml"
    scene.write_text(f"[grid]\nnx = {n}\nny = {n}\nlx = 3e-3\nly = 3e-3\n{BODY[body]}{load}"
                     f"[method]\n{method}\n")
    out = tmp / f"out_{name.replace(' ', '_')}_{n}"
    result = subprocess.run([str(BUILD / "bench" / "bench_peak_rss"), str(BUILD / "coatfft"),
                             "run", str(scene), "-o", str(out)],
                            capture_output=True, text=True, check=True)
    # bench_peak_rss's `key = value` lines, after what the program itself prints
    values = dict(line.split(" = ", 1) for line in result.stdout.splitlines() if " = " in line)
    summary = json.loads((out / "summary.json").read_text())
    measured = float(values["peak_rss_mb"]) * 2**20
    estimate = summary["estimated_memory_bytes"]
    return [name, n, body, f"{estimate / 2**20:.1f}", f"{measured / 2**20:.1f}",
            f"{measured / estimate:.2f}"]


def main():
    header = ["case", "n", "body", "estimate_mib", "peak_rss_mib", "measured_over_estimate"]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for case in CASES:
            rows.append(run_case(pathlib.Path(tmp), *case))
    target = ROOT / "bench" / "results" / "memory_estimate.csv"
    with open(target, "w", newline="") as f:
        csv.writer(f).writerows([header] + rows)
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for row in rows:
        print("| " + " | ".join(str(v) for v in row) + " |")


if __name__ == "__main__":
    main()
