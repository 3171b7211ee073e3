#!/usr/bin/python3
"""Plot an FRF table written by `coatfft frf`: H(k) / H_substrate(k) against k h (log x).

Input: a CSV with the header  k,kh_total,frf,frf_over_substrate  (lines starting with '#' are
skipped). Output: a PNG. For a homogeneous body (kh_total = 0) the x axis falls back to k [rad/m].

Usage: scripts/plot_frf.py table.csv [out.png] [--title TEXT]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HEADER = ["k", "kh_total", "frf", "frf_over_substrate"]


def read_table(path):
    with open(path, newline="") as f:
        rows = [line for line in f if line.strip() and not line.lstrip().startswith("#")]
    reader = csv.reader(rows)
    header = [h.strip() for h in next(reader, [])]
    if header != HEADER:
        raise SystemExit(f"{path}: header {header}, expected {HEADER}")
    cols = {name: [] for name in HEADER}
    for lineno, row in enumerate(reader, start=2):
        if len(row) != len(HEADER):
            raise SystemExit(f"{path}: data row {lineno} has {len(row)} fields, expected 4")
        for name, value in zip(HEADER, row):
            cols[name].append(float(value))
    if not cols["k"]:
        raise SystemExit(f"{path}: no data rows")
    return cols


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("table")
    parser.add_argument("output", nargs="?", default=None)
    parser.add_argument("--title", default=None)
    args = parser.parse_args(argv)
    cols = read_table(args.table)
    output = args.output or (args.table.rsplit(".", 1)[0] + ".png")

    layered = any(v > 0 for v in cols["kh_total"])
    x = cols["kh_total"] if layered else cols["k"]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.semilogx(x, cols["frf_over_substrate"], lw=1.8)
    ax.axhline(1.0, color="0.6", lw=0.8, ls="--")
    ax.set_xlabel(r"$k\,h_{\mathrm{total}}$" if layered else r"$k$ [rad/m]")
    ax.set_ylabel(r"$H(k)\,/\,H_{\mathrm{substrate}}(k)$")
    ax.set_title(args.title or "Surface compliance relative to the bare substrate")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(output, dpi=150)
    print(output)


if __name__ == "__main__":
    main(sys.argv[1:])
