"""Pictures of what a ``coatfft run`` wrote: ``python3 -m coatfft.plot OUTDIR [--to FOLDER]``.

Draws a PNG for each kind of output the folder holds (docs/python.md, "Pictures"):

* ``pressure.png``: the contact pressure (or the known pressure) over the surface, with the
  contact outline (p > 0) of a contact; for a sweep, the largest value's;
* ``gap.png``: the gap of a contact, with the same outline;
* ``uz.png``: the surface displacement of a known pressure;
* ``von_mises_planes.png``: von Mises on each plane of ``[stress] depths``;
* ``von_mises_section.png``: von Mises on the section y = 0, with the interfaces of the body;
* ``area_load.png``: the contact area fraction against the load of a sweep (sweep.csv).

The pictures go to FOLDER (default OUTDIR/plots), created when missing; a FOLDER that holds
anything but PNG files is refused, so that nothing but earlier pictures is ever replaced. A
folder that is not a run's (no summary.json) is refused with one line and exit status 2.
"""
import argparse
import csv
import json
import pathlib
import sys

import numpy as np

UNITS = {"Pa": 1.0, "MPa": 1e6, "GPa": 1e9}


class PlotError(Exception):
    """A folder or file that cannot be drawn: one line for the user."""


def cell_centres(n, length):
    """The cell centres -L/2 + (i + 1/2) L/n [m] of one axis of coatfft's grid."""
    return -0.5 * length + (np.arange(n) + 0.5) * length / n


def surface_map(plt, summary, field, title, label, contact=None):
    """A field (ny, nx) over the surface [mm], with the outline of `contact` when given."""
    x = cell_centres(summary["nx"], summary["lx"]) * 1e3
    y = cell_centres(summary["ny"], summary["ly"]) * 1e3
    fig, ax = plt.subplots(figsize=(5.2, 4.2))
    mesh = ax.pcolormesh(x, y, field, shading="nearest", cmap="viridis")
    if contact is not None and contact.any() and not contact.all():
        ax.contour(x, y, contact.astype(float), levels=[0.5], colors="w", linewidths=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(title)
    fig.colorbar(mesh, ax=ax, label=label)
    fig.tight_layout()
    return fig


def last_of(array):
    """The largest value's field of a sweep's stacked array (n, ny, nx), or the field itself."""
    return array[-1] if array.ndim == 3 else array


def contact_pictures(plt, folder, summary, unit):
    figures = {}
    pressure_file, gap_file = folder / "pressure.npy", folder / "gap.npy"
    contact = None
    which = " (the sweep's largest value)" if "sweep" in summary else ""
    if pressure_file.is_file():
        p = last_of(np.load(pressure_file))
        contact = p > 0 if "contact_area" in summary else None
        figures["pressure.png"] = surface_map(plt, summary, p / UNITS[unit], "pressure" + which,
                                              f"p [{unit}]", contact)
    if gap_file.is_file():
        gap = last_of(np.load(gap_file))
        figures["gap.png"] = surface_map(plt, summary, gap * 1e6, "gap" + which, "g [um]",
                                         contact)
    if (folder / "uz.npy").is_file() and "contact_area" not in summary:
        uz = np.load(folder / "uz.npy")
        figures["uz.png"] = surface_map(plt, summary, uz * 1e6, "surface displacement",
                                        "uz [um]")
    return figures


def section_picture(plt, folder, summary, unit):
    vm = np.load(folder / "von_mises_section.npy") / UNITS[unit]
    section = summary["stress"]["section"]
    nz, nx = vm.shape
    if nx != summary["nx"] or nz != section["nz"]:
        raise PlotError(f"{folder / 'von_mises_section.npy'}: shape {vm.shape} does not match "
                        "summary.json")
    x = cell_centres(nx, summary["lx"]) * 1e3
    z = section["depth_max"] * np.arange(1, nz + 1) / nz * 1e3
    fig, ax = plt.subplots(figsize=(7, 3.6))
    mesh = ax.pcolormesh(x, z, vm, shading="nearest", cmap="viridis")
    for interface in summary["stress"].get("interfaces", []):
        ax.axhline(interface["depth"] * 1e3, color="w", ls="--", lw=0.8)
    ax.invert_yaxis()
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("depth z [mm]")
    ax.set_title("von Mises stress on y = 0 (dashed: interfaces)")
    fig.colorbar(mesh, ax=ax, label=f"[{unit}]")
    fig.tight_layout()
    return fig


def planes_picture(plt, folder, summary, unit):
    vm = np.load(folder / "von_mises.npy") / UNITS[unit]
    depths = summary["stress"]["depths"]
    x = cell_centres(summary["nx"], summary["lx"]) * 1e3
    y = cell_centres(summary["ny"], summary["ly"]) * 1e3
    fig, axes = plt.subplots(1, len(depths), figsize=(3.6 * len(depths), 3.4), squeeze=False)
    for ax, plane, z in zip(axes[0], vm, depths):
        mesh = ax.pcolormesh(x, y, plane, shading="nearest", cmap="viridis")
        ax.set_aspect("equal")
        ax.set_title(f"z = {z * 1e3:.4g} mm")
        ax.set_xlabel("x [mm]")
        fig.colorbar(mesh, ax=ax, label=f"von Mises [{unit}]")
    axes[0][0].set_ylabel("y [mm]")
    fig.tight_layout()
    return fig


def sweep_picture(plt, folder):
    with open(folder / "sweep.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    load = [float(r["load"]) for r in rows]
    area = [float(r["area_fraction"]) for r in rows]
    fig, ax = plt.subplots(figsize=(5, 3.8))
    ax.plot(load, area, "o-")
    ax.set_xlabel("load W [N]")
    ax.set_ylabel("contact area fraction A/A0")
    ax.set_title("area against load")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    return fig


def pictures(folder, unit):
    """Every picture the folder's outputs allow: {file name: figure}."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    summary_file = folder / "summary.json"
    if not summary_file.is_file():
        raise PlotError(f"{folder}: no summary.json: not the output folder of a coatfft run")
    summary = json.loads(summary_file.read_text())
    figures = contact_pictures(plt, folder, summary, unit)
    if (folder / "von_mises.npy").is_file():
        figures["von_mises_planes.png"] = planes_picture(plt, folder, summary, unit)
    if (folder / "von_mises_section.npy").is_file():
        figures["von_mises_section.png"] = section_picture(plt, folder, summary, unit)
    if (folder / "sweep.csv").is_file():
        figures["area_load.png"] = sweep_picture(plt, folder)
    return plt, figures


def target_folder(folder, to):
    """The folder of the pictures (made once there is something to draw); refused, before any
    work, when it holds anything but pictures."""
    target = to if to is not None else folder / "plots"
    if target.exists():
        if not target.is_dir():
            raise PlotError(f"{target}: exists and is not a folder")
        others = [p.name for p in target.iterdir() if p.suffix != ".png" or not p.is_file()]
        if others:
            raise PlotError(f"{target}: holds {others[0]!r}, which is not a picture; give another "
                            "folder with --to")
    return target


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m coatfft.plot",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path, help="a coatfft run's output folder")
    parser.add_argument("--to", type=pathlib.Path, help="folder of the PNGs (OUTDIR/plots)")
    parser.add_argument("--unit", choices=sorted(UNITS), default="MPa",
                        help="unit of pressures and stresses (MPa)")
    args = parser.parse_args(argv)
    try:
        target = target_folder(args.folder, args.to)
        plt, figures = pictures(args.folder, args.unit)
        if not figures:
            raise PlotError(f"{args.folder}: no output to draw (no .npy field nor sweep.csv)")
        target.mkdir(parents=True, exist_ok=True)
        for name, figure in figures.items():
            figure.savefig(target / name, dpi=120)
            plt.close(figure)
            print(target / name)
    except (PlotError, OSError, KeyError, ValueError) as error:
        print(f"coatfft.plot: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
