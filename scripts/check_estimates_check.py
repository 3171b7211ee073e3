#!/usr/bin/python3
"""`coatfft check`'s estimates of memory and time against a run, on every example scene.

For each examples/scenes/*.toml: `coatfft check` gives estimated_memory_bytes and
estimated_seconds (setup + applications x apply, the cost model of docs/auto.md); `coatfft run`
under bench_peak_rss gives the peak resident set and summary.json the times: setup_seconds plus
apply_seconds for a known pressure, setup_seconds plus solve_seconds for a contact. Each run is
repeated (--reps, default 3) and the medians are kept. Writes bench/results/check_estimates.csv
and prints a Markdown table.

Usage: scripts/check_estimates_check.py [BUILD_DIR] [--reps N]   (default: build, 3)
"""
import csv
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
BUILD = pathlib.Path(ARGS[0] if ARGS else ROOT / "build").resolve()
REPS = int(sys.argv[sys.argv.index("--reps") + 1]) if "--reps" in sys.argv else 3
COATFFT = str(BUILD / "coatfft")


def check(scene):
    out = subprocess.run([COATFFT, "check", str(scene)], capture_output=True, text=True,
                         check=True)
    plan = json.loads(out.stdout)
    return plan["estimated_memory_bytes"], plan["estimated_seconds"]["total"], plan["method"]


def run(scene, outdir):
    result = subprocess.run([str(BUILD / "bench" / "bench_peak_rss"), COATFFT, "run",
                             str(scene), "-o", str(outdir), "--quiet"],
                            capture_output=True, text=True, check=True)
    values = dict(line.split(" = ") for line in result.stdout.strip().splitlines())
    summary = json.loads((outdir / "summary.json").read_text())
    work = summary["setup_seconds"] + summary.get("solve_seconds", summary["apply_seconds"])
    return float(values["peak_rss_mb"]) * 2**20, work


def main():
    header = ["scene", "method", "estimated_mib", "peak_rss_mib", "memory_ratio",
              "estimated_s", "measured_s", "time_ratio"]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in sorted((ROOT / "examples" / "scenes").glob("*.toml")):
            memory, seconds, method = check(scene)
            runs = [run(scene, pathlib.Path(tmp) / f"{scene.stem}_{r}") for r in range(REPS)]
            rss = statistics.median(r[0] for r in runs)
            work = statistics.median(r[1] for r in runs)
            rows.append([scene.name, method, f"{memory / 2**20:.2f}", f"{rss / 2**20:.2f}",
                         f"{rss / memory:.2f}", f"{seconds:.4g}", f"{work:.4g}",
                         f"{work / seconds:.2f}"])
            print(",".join(rows[-1]), file=sys.stderr)
    target = ROOT / "bench" / "results" / "check_estimates.csv"
    with open(target, "w", newline="") as f:
        f.write(f"# scripts/check_estimates_check.py, reps = {REPS}, load average "
                f"{os.getloadavg()[0]:.1f} at the end\n")
        csv.writer(f).writerows([header] + rows)
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for row in rows:
        print("| " + " | ".join(str(v) for v in row) + " |")


if __name__ == "__main__":
    main()
