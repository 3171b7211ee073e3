#!/usr/bin/python3
"""Plot the real contact area against the load of docs/validation/rough_contact.md.

Input: the markdown that `rough_contact_table` writes; its table "Area against load: bare and
coated steel" gives A/A0 at each p_m/(E* g) for steel, TiN 5 um on steel and a soft 5 um coating.
Drawn on log-log axes with the near-linear law A/A0 = kappa p_m/(E* g) for kappa = 2 (Hyun et al.
2004) and sqrt(8/pi) (Persson 2001, vanishing load). Output: a PNG (default
docs/figures/rough_contact_area.png).

Usage: scripts/plot_rough_contact.py [TABLE.md] [out.png]
"""
import argparse
import math
import pathlib

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
HEADING = "## Area against load"


def read_body_table(path):
    """The rows of the body table: load, then A/A0 for steel, TiN and the soft coating."""
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(HEADING))
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("## "):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 7 and cells[0][0].isdigit():
            rows.append([float(cells[0]), float(cells[1]), float(cells[3]), float(cells[5])])
    if not rows:
        raise SystemExit(f"{path}: no rows under '{HEADING}'")
    return np.array(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table", nargs="?", type=pathlib.Path,
                        default=ROOT / "docs" / "validation" / "rough_contact.md")
    parser.add_argument("out", nargs="?", type=pathlib.Path,
                        default=ROOT / "docs" / "figures" / "rough_contact_area.png")
    args = parser.parse_args()
    data = read_body_table(args.table)
    load = data[:, 0]
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for column, label, marker in ((1, "steel", "o"), (2, "TiN 5 um on steel", "s"),
                                  (3, "soft 5 um (E = 20 GPa) on steel", "^")):
        ax.loglog(load, data[:, column], marker=marker, label=label)
    line = np.array([load.min(), load.max()])
    ax.loglog(line, 2.0 * line, "k--", lw=1, label="kappa = 2 (Hyun et al. 2004)")
    ax.loglog(line, math.sqrt(8 / math.pi) * line, "k:", lw=1,
              label="kappa = sqrt(8/pi) (Persson 2001)")
    ax.set_xlabel("p_m / (E* g)   (E* of the steel substrate, g the rms slope)")
    ax.set_ylabel("A / A0")
    ax.set_title("Rough contact on periodic surfaces, 512^2 cells")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
