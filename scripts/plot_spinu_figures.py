#!/usr/bin/python3
"""Figures 2 and 3 of Spinu (2021) from `bench_figures DIR` data.

    scripts/plot_spinu_figures.py [DATA_DIR] [--outdir docs/figures]

DATA_DIR (default bench/results/spinu_figures) holds fig2a_dcfft_error_field.csv,
fig2b_dcfft_error_vs_n.csv, fig3a_frf_alpha.csv and fig3b_frf_g0.csv. Writes
spinu_fig2_dcfft_hertz.png ((a) iso-contours of the DC-FFT error at 64^2, (b) max error against N)
and spinu_fig3_frf_hertz.png ((a) FRF pipelines' error along the x axis for alpha = 2, 4, 8, 12,
(b) frf-spectral's error for different g(0) tolerances, (c) the same minus the regularized g(0)
curve: a shift by a constant). Error = (u - u_exact) / u_exact(0), homogeneous Hertz.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    with open(path) as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    return list(csv.DictReader(lines))


def figure2(data, outdir):
    field = read(os.path.join(data, "fig2a_dcfft_error_field.csv"))
    x = np.array([float(r["x_over_a"]) for r in field])
    y = np.array([float(r["y_over_a"]) for r in field])
    e = np.array([float(r["err"]) for r in field])
    n = int(round(np.sqrt(len(e))))
    xs, ys = np.unique(x), np.unique(y)
    grid = np.zeros((n, n))
    ix = np.searchsorted(xs, x)
    iy = np.searchsorted(ys, y)
    grid[iy, ix] = e
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 5))
    cs = a.contourf(xs, ys, grid * 100, levels=20, cmap="RdBu_r")
    a.contour(xs, ys, grid * 100, levels=10, colors="k", linewidths=0.4)
    a.add_patch(plt.Circle((0, 0), 1.0, fill=False, linestyle="--", color="k", linewidth=0.8))
    fig.colorbar(cs, ax=a, label="(u - u_exact) / u_exact(0)  [%]")
    a.set_aspect("equal")
    a.set_xlabel("x / a")
    a.set_ylabel("y / a")
    a.set_title(f"(a) DC-FFT error, Hertz, {n} x {n} cells (dashed: r = a)")
    conv = read(os.path.join(data, "fig2b_dcfft_error_vs_n.csv"))
    ns = np.array([int(r["N"]) for r in conv])
    b.loglog(ns, [float(r["max_err"]) * 100 for r in conv], "o-", label="max |error|")
    b.loglog(ns, [float(r["rms_err"]) * 100 for r in conv], "s--", label="RMS error")
    b.loglog(ns, 100 * float(conv[0]["max_err"]) * (ns[0] / ns) ** 1, "k:", linewidth=0.8,
             label="slope -1")
    b.loglog(ns, 100 * float(conv[0]["rms_err"]) * (ns[0] / ns) ** 2, "k-.", linewidth=0.8,
             label="slope -2")
    b.axhline(1.5, color="grey", linewidth=0.8)
    b.text(ns[0], 1.6, "Spinu (2021): < 1.5% at 32 x 32", fontsize=8, color="grey")
    b.set_xlabel("N (N x N cells on [-1.5a, 1.5a]^2)")
    b.set_ylabel("error / u_exact(0)  [%]")
    b.set_title("(b) influence of grid density")
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(outdir, "spinu_fig2_dcfft_hertz.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def figure3(data, outdir):
    rows = read(os.path.join(data, "fig3a_frf_alpha.csv"))
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(17, 5))
    colours = {2.0: "tab:red", 4.0: "tab:orange", 8.0: "tab:green", 12.0: "tab:blue"}
    for method, style in (("frf-spectral", "-"), ("frf-dcfft", "--")):
        for alpha in sorted({float(r["alpha"]) for r in rows}):
            sel = [r for r in rows if r["method"] == method and float(r["alpha"]) == alpha]
            a.plot([float(r["x_over_a"]) for r in sel], [float(r["err"]) * 100 for r in sel],
                   style, color=colours.get(alpha, "k"), label=f"{method}, alpha = {alpha:g}")
    a.set_xlabel("x / a  (y = 0, N = 65)")
    a.set_ylabel("(u - u_exact) / u_exact(0)  [%]")
    a.set_title("(a) FRF pipelines: influence of alpha (g0 regularized)")
    a.grid(True, alpha=0.3)
    a.legend(fontsize=7)
    g0 = read(os.path.join(data, "fig3b_frf_g0.csv"))
    keys = list(dict.fromkeys((r["g0"], r["g0_tol"]) for r in g0))
    ref = {r["x_over_a"]: float(r["err"]) for r in g0 if r["g0"] == "regularized"}
    for name, tol in keys:
        sel = [r for r in g0 if r["g0"] == name and r["g0_tol"] == tol]
        rel = abs(float(sel[0]["g0_value"]) / float(next(iter(
            r["g0_value"] for r in g0 if r["g0"] == "regularized"))) - 1)
        lab = "regularized" if name == "regularized" else \
            f"quadrature tol {float(tol):.0e} (g0 rel. err {rel:.1e})"
        xs = [float(r["x_over_a"]) for r in sel]
        b.plot(xs, [float(r["err"]) * 100 for r in sel], label=lab)
        c.plot(xs, [(float(r["err"]) - ref[r["x_over_a"]]) * 100 for r in sel], label=lab)
    b.set_xlabel("x / a  (y = 0, N = 65, alpha = 2, frf-spectral)")
    b.set_ylabel("(u - u_exact) / u_exact(0)  [%]")
    b.set_title("(b) influence of the g(0) computation")
    c.set_xlabel("x / a")
    c.set_ylabel("error minus the regularized g(0) curve  [%]")
    c.set_title("(c) = (b) minus regularized: a constant shift")
    for ax in (b, c):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(outdir, "spinu_fig3_frf_hertz.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("data", nargs="?", default="bench/results/spinu_figures")
    ap.add_argument("--outdir", default="docs/figures")
    args = ap.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    for f in (figure2, figure3):
        print("written", f(args.data, args.outdir))


if __name__ == "__main__":
    main()
