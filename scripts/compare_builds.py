#!/usr/bin/python3
"""Two builds of the coatfft program side by side, in one run: the same scenes, alternated
between the builds round by round, so that machine noise falls on both alike.

Usage: scripts/compare_builds.py OLD_COATFFT NEW_COATFFT OUTPUT.csv [--rounds R] [--n N]

For each scene (every method on a coated or homogeneous body at N x N cells, and a contact
solve) it records the median over R rounds of setup_seconds and apply_seconds (each the median
of 5 applications), their ratio new/old, and the largest difference between the two builds'
uz.npy relative to max |uz| (0 when the numbers did not change). Then every bundled example
(examples/scenes/*.toml) is run once by each build: the summary.json keys whose values differ
(timings and warnings aside) and the .npy files that are not bitwise equal are printed, and
written to OUTPUT.csv's comment lines.
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile

import numpy as np

BODIES = {
    "steel": '[substrate]\nmaterial = "steel"\n',
    "tin_on_steel": '[substrate]\nmaterial = "steel"\n\n[[coating]]\n'
                    'material = "titanium_nitride"\nthickness = 2.0e-5\ninterface = "bonded"\n',
}
CASES = [  # (label, body, [method] lines, load section)
    ("dcfft", "steel", 'name = "dcfft"', "pressure"),
    ("direct", "steel", 'name = "direct"', "pressure_small"),
    ("frf-split", "tin_on_steel", 'name = "frf-split"', "pressure"),
    ("frf-dcfft a2", "tin_on_steel", 'name = "frf-dcfft"\nalpha = 2', "pressure"),
    ("frf-dcfft a4", "tin_on_steel", 'name = "frf-dcfft"\nalpha = 4', "pressure"),
    ("frf-spectral a2", "tin_on_steel", 'name = "frf-spectral"\nalpha = 2', "pressure"),
    ("contact frf-split", "tin_on_steel", 'name = "frf-split"', "contact"),
]
LOADS = {
    "pressure": '[pressure]\nkind = "hertz"\np0 = 1.0e9\na = 1.0e-3\n',
    "pressure_small": '[pressure]\nkind = "hertz"\np0 = 1.0e9\na = 1.0e-3\n',
    "contact": '[contact]\nindenter = "sphere"\nradius = 0.02\nload = 200.0\n',
}


def scene(n, body, method, load):
    n = 32 if load == "pressure_small" else n
    return (f"[grid]\nnx = {n}\nny = {n}\nlx = 3.0e-3\nly = 3.0e-3\n\n{BODIES[body]}\n"
            f"{LOADS[load]}\n[method]\n{method}\n")


def run(binary, scene_file, out):
    subprocess.run([binary, "run", str(scene_file), "-o", str(out), "--repeat", "5"], check=True,
                   stdout=subprocess.DEVNULL)
    summary = json.loads((out / "summary.json").read_text())
    return summary, np.load(out / "uz.npy")


EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples" / "scenes"


def without_timings(value):
    """summary.json without the keys that measure time and the warnings that may name it."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items()
                if not k.endswith("seconds") and k != "warnings"}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def compare_examples(old, new, tmp):
    """One line per bundled example: the summary keys and .npy files the two builds disagree on."""
    lines = []
    for scene_file in sorted(EXAMPLES.glob("*.toml")):
        outs = {w: tmp / f"example_{scene_file.stem}_{w}" for w in ("old", "new")}
        codes = {w: subprocess.run([b, "run", str(scene_file), "-o", str(outs[w]), "--quiet"],
                                   capture_output=True).returncode
                 for w, b in (("old", old), ("new", new))}
        if codes["old"] != codes["new"] or codes["old"] not in (0, 3):
            lines.append(f"{scene_file.name}: exit {codes['old']} (old), {codes['new']} (new)")
            continue
        a, b = (without_timings(json.loads((outs[w] / "summary.json").read_text()))
                for w in ("old", "new"))
        keys = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
        fields = sorted(f.name for f in outs["old"].glob("*.npy")
                        if not np.array_equal(np.load(f), np.load(outs["new"] / f.name),
                                              equal_nan=True))
        lines.append(f"{scene_file.name}: summary keys differing {keys or 'none'}, "
                     f".npy differing {fields or 'none'}")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("output")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--n", type=int, default=512)
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for label, body, method, load in CASES:
            scene_file = tmp / "scene.toml"
            scene_file.write_text(scene(args.n, body, method, load))
            times = {"old": ([], []), "new": ([], [])}
            uz = {}
            for r in range(args.rounds):
                for which in ("old", "new") if r % 2 == 0 else ("new", "old"):
                    out = tmp / f"{which}_{r}"
                    summary, uz[which] = run(getattr(args, which), scene_file, out)
                    times[which][0].append(summary["setup_seconds"])
                    times[which][1].append(summary["apply_seconds"])
            diff = float(np.max(np.abs(uz["new"] - uz["old"])) / np.max(np.abs(uz["old"])))
            med = {w: (statistics.median(s), statistics.median(a)) for w, (s, a) in times.items()}
            rows.append((label, med["old"][0], med["new"][0], med["new"][0] / med["old"][0],
                         med["old"][1], med["new"][1], med["new"][1] / med["old"][1], diff))
            print(f"{label}: setup {rows[-1][3]:.2f}x, apply {rows[-1][6]:.2f}x, uz diff {diff:.1e}",
                  file=sys.stderr)
        examples = compare_examples(args.old, args.new, tmp)
        print("\n".join(examples), file=sys.stderr)
    with open(args.output, "w") as f:
        f.write(f"# n = {args.n}\n# rounds = {args.rounds}\n# old = {args.old}\n"
                f"# new = {args.new}\n")
        f.writelines(f"# example {line}\n" for line in examples)
        f.write("case,setup_old_s,setup_new_s,setup_ratio,apply_old_s,apply_new_s,apply_ratio,"
                "uz_max_rel_diff\n")
        for row in rows:
            f.write(f"{row[0]},{row[1]:.6g},{row[2]:.6g},{row[3]:.3f},{row[4]:.6g},{row[5]:.6g},"
                    f"{row[6]:.3f},{row[7]:.3g}\n")


if __name__ == "__main__":
    main()
