#!/usr/bin/python3
"""Plot the von Mises stress on the section y = 0 of a `coatfft run` with [stress] section = "xz".

Input: the run's output folder (von_mises_section.npy of shape (nz, nx) and summary.json, whose
"nx", "lx" and "stress" -> "section" give the axes). The rows are the depths depth_max k/nz,
k = 1..nz; the columns the cell centres x_i = -lx/2 + (i + 1/2) lx/nx. Interfaces of the body
(summary "stress" -> "interfaces") are drawn as dashed lines. Output: a PNG.

Usage: scripts/plot_stress_section.py OUTPUT_FOLDER [out.png] [--unit Pa|MPa|GPa]
"""
import argparse
import json
import pathlib

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNITS = {"Pa": 1.0, "MPa": 1e6, "GPa": 1e9}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path)
    parser.add_argument("out", nargs="?", type=pathlib.Path)
    parser.add_argument("--unit", choices=sorted(UNITS), default="MPa")
    args = parser.parse_args()

    summary_file = args.folder / "summary.json"
    section_file = args.folder / "von_mises_section.npy"
    for f in (summary_file, section_file):
        if not f.is_file():
            raise SystemExit(f"{f}: not found (run a scene with [stress] section = \"xz\")")
    summary = json.loads(summary_file.read_text())
    stress = summary.get("stress", {})
    if "section" not in stress:
        raise SystemExit(f"{summary_file}: no stress section in this run")
    vm = np.load(section_file) / UNITS[args.unit]
    nz, nx = vm.shape
    lx, depth_max = summary["lx"], stress["section"]["depth_max"]
    if nx != summary["nx"] or nz != stress["section"]["nz"]:
        raise SystemExit(f"{section_file}: shape {vm.shape} does not match summary.json")
    x = (-0.5 * lx + (np.arange(nx) + 0.5) * lx / nx) * 1e3
    z = depth_max * np.arange(1, nz + 1) / nz * 1e3

    fig, ax = plt.subplots(figsize=(7, 3.6))
    mesh = ax.pcolormesh(x, z, vm, shading="nearest", cmap="viridis")
    for interface in stress.get("interfaces", []):
        ax.axhline(interface["depth"] * 1e3, color="w", ls="--", lw=0.8)
    peak = stress["max_von_mises"]
    ax.plot(peak["x"] * 1e3, peak["z"] * 1e3, "r+", ms=10, label="largest von Mises (all planes)")
    ax.invert_yaxis()
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("depth z [mm]")
    ax.set_title("von Mises stress on y = 0")
    ax.legend(loc="lower right", fontsize=8)
    fig.colorbar(mesh, ax=ax, label=f"[{args.unit}]")
    fig.tight_layout()
    out = args.out or args.folder / "von_mises_section.png"
    fig.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
