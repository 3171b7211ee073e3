#!/usr/bin/python3
"""Generated blocks in the docs: a benchmark CSV rendered as a markdown table between markers.

    scripts/markdown_blocks.py DOC.md NAME FILE.csv [--columns c1,c2,...] [--view VIEW]

replaces the lines between `<!-- BEGIN GENERATED NAME -->` and `<!-- END GENERATED NAME -->` of
DOC.md (which must already hold both markers: a doc names where its numbers go) with the CSV
rendered by VIEW, so that the numbers quoted in the docs are the ones last measured:

    csv (default)       the CSV's `# key = value` headers as a list and its rows as a table
                        (--columns: a subset of the columns, in that order)
    direct-speedup      bench_dcfft's CSV (bench/results/dcfft.csv): direct summation against
                        DC-FFT, one row per N (the `direct` and `dcfft_small` rows)
    coated-convergence  bench_sweep's CSV (bench/results/sweep.csv): max error of every FRF method
                        on the coated cases, rows (case, method, alpha), columns N

scripts/plot_pareto.py uses the same functions for its block.
"""
import argparse
import math
import re
import sys


def read_csv(path):
    """(comment lines, {key: value} of the `# key = value` comments, rows as lists of strings;
    the first row is the column names)."""
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if line.strip()]
    comments = [line for line in lines if line.startswith("#")]
    keys = {}
    for line in comments:
        m = re.match(r"#\s*([^=]+?)\s*=\s*(.*)$", line)
        if m:
            keys[m.group(1)] = m.group(2)
    data = [line.split(",") for line in lines if not line.startswith("#")]
    return comments, keys, data


def read_records(path, required):
    """The CSV's `# key = value` comments and its rows as dicts; exits if a column is missing."""
    _, keys, data = read_csv(path)
    if not data:
        sys.exit(f"markdown_blocks.py: {path} has no rows")
    missing = [c for c in required if c not in data[0]]
    if missing:
        sys.exit(f"markdown_blocks.py: {path} has no column(s) {', '.join(missing)}")
    return keys, [dict(zip(data[0], d)) for d in data[1:]]


def table(header, rows, align=None):
    """A markdown table; align: one of '---' / '---:' per column (default: all right-aligned)."""
    align = align or ["---:"] * len(header)
    out = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    return out + ["| " + " | ".join(r) + " |" for r in rows]


def csv_as_markdown(path, columns=None):
    """The CSV's comment lines (verbatim, in a code block) then its rows as a markdown table."""
    comments, _, data = read_csv(path)
    comments = ["```"] + comments + ["```"] if comments else []
    if not data:
        return comments
    keep = range(len(data[0]))
    if columns:
        missing = [c for c in columns if c not in data[0]]
        if missing:
            sys.exit(f"markdown_blocks.py: {path} has no column(s) {', '.join(missing)}")
        keep = [data[0].index(c) for c in columns]
    rows = [[d[i] if i < len(d) else "" for i in keep] for d in data]
    return comments + [""] + table(rows[0], rows[1:], ["---"] * len(rows[0]))


def direct_speedup(path):
    """Direct summation against DC-FFT from bench_dcfft's CSV: for every N with a `direct` row,
    both medians, the speed-up (the direct row's `ratio`) and the max relative difference (the
    `dcfft_small` row's `rel_err_inf`)."""
    keys, records = read_records(path, ["method", "N", "threads", "apply_ms_median", "ratio",
                                        "rel_err_inf"])
    small = {r["N"]: r for r in records if r["method"] == "dcfft_small"}
    rows = []
    for d in sorted((r for r in records if r["method"] == "direct"), key=lambda r: int(r["N"])):
        s = small.get(d["N"])
        if s is None:
            sys.exit(f"markdown_blocks.py: {path} has a direct row but no dcfft_small row at "
                     f"N = {d['N']}")
        rows.append([f"{d['N']}^2", f"{float(d['apply_ms_median']):.3g}",
                     f"{float(s['apply_ms_median']):.3g}", f"**{float(d['ratio']):.3g}x**",
                     f"{float(s['rel_err_inf']):.1e}"])
    if not rows:
        sys.exit(f"markdown_blocks.py: {path} has no direct rows")
    threads = ", ".join(sorted({r["threads"] for r in records if r["method"] == "direct"}))
    return [f"bench_dcfft run of {keys.get('date', '(no date)')} on {keys.get('cpu', '?')}, "
            f"{keys.get('compiler', '?')}; medians of single applications, threads = {threads}; "
            "speed-up = direct median / DC-FFT median; rel. diff. = max |u_dcfft - u_direct| / "
            "max |u_direct|:", ""] + table(
        ["N", "direct median [ms]", "DC-FFT median [ms]", "speed-up", "rel. diff. (max)"], rows)


def coated_convergence(path):
    """Max error against the Hankel reference of frf-split and of the two FRF pipelines of Spinu
    (2021) (g(0) regularized, alpha 2, 4, 8) on every coated case of a bench_sweep CSV: rows (case,
    method, alpha), columns N, then the order between the two largest N and alpha x the error
    there."""
    keys, records = read_records(path, ["case", "method", "N", "alpha", "g0", "max_err"])
    coated = [r for r in records if r["case"].startswith("coated")]
    if not coated:
        sys.exit(f"markdown_blocks.py: {path} has no coated case (case names coated_*)")
    grids = sorted({int(r["N"]) for r in coated})
    errors = {}  # (case, method, alpha) -> {N: max_err}
    for r in coated:
        if r["method"] == "frf-split" or r["g0"] == "regularized":
            key = (r["case"], r["method"], float(r["alpha"]))
            errors.setdefault(key, {})[int(r["N"])] = float(r["max_err"])
    order = {"frf-split": 0, "frf-spectral": 1, "frf-dcfft": 2}
    cases = list(dict.fromkeys(r["case"] for r in coated))
    rows = []
    for key in sorted(errors, key=lambda k: (cases.index(k[0]), order.get(k[1], 3), k[2])):
        case, method, alpha = key
        by_n = errors[key]
        ns = sorted(by_n)
        rate = math.log2(by_n[ns[-2]] / by_n[ns[-1]]) / math.log2(ns[-1] / ns[-2]) \
            if len(ns) > 1 else None
        rows.append([case, method, f"{alpha:g}" if alpha > 0 else ""]
                    + [f"{by_n[n]:.2e}" if n in by_n else "—" for n in grids]
                    + ["" if rate is None else f"{rate:.2f}",
                       f"{alpha * by_n[ns[-1]]:.2e}" if alpha > 0 else ""])
    out = table(["case", "method", "alpha"] + [f"N = {n}" for n in grids]
                + ["order (last two N)", "alpha x error at largest N"], rows,
                ["---", "---", "---:"] + ["---:"] * (len(grids) + 2))
    out += ["", "Max error, (u - u_ref) / u_ref(0), over the N x N cells on [-1.5a, 1.5a]^2; "
            "g(0) regularized for frf-spectral and frf-dcfft; order: log2 of the ratio of the "
            "errors at the two largest N over log2 of their ratio; — : not run (caps: "
            f"`{keys.get('caps', '?')}`). Sweep of {keys.get('date', '(no date)')} "
            f"(mode {keys.get('mode', '?')}). Cases:", ""]
    references = set()
    for case in cases:
        body, _, reference = keys.get("case " + case, "(no description)").partition("; reference: ")
        out.append(f"- {case}: {body}")
        references.add(reference)
    if len(references) == 1 and "" not in references:
        out += ["", f"Reference: {references.pop()}."]
    same = lambda r: (r["case"], r["method"], r["N"], r["alpha"])  # noqa: E731
    regularized = {same(r): float(r["max_err"]) for r in coated if r["g0"] == "regularized"}
    shift = [abs(float(q["max_err"]) - regularized[same(q)]) / regularized[same(q)]
             for q in coated if q["g0"] == "quadrature" and same(q) in regularized]
    if shift:
        out += ["", "g(0) by quadrature (the sweep's `g0 = quadrature` rows) instead of "
                f"regularized changes these max errors by at most {100 * max(shift):.2g} %."]
    return out


VIEWS = {"direct-speedup": direct_speedup, "coated-convergence": coated_convergence}


def replace_block(doc_path, begin, end, lines):
    """Replaces the text from the line `begin` to the line `end` (both kept) with lines."""
    with open(doc_path) as f:
        text = f.read()
    if begin not in text or end not in text or text.index(end) < text.index(begin):
        sys.exit(f"markdown_blocks.py: {doc_path} has no block '{begin}' ... '{end}'")
    head = text[: text.index(begin)]
    tail = text[text.index(end) + len(end):]
    with open(doc_path, "w") as f:
        f.write(head + "\n".join([begin, ""] + lines + ["", end]) + tail)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("doc")
    ap.add_argument("name")
    ap.add_argument("csv")
    ap.add_argument("--columns", default=None, help="comma-separated subset of the CSV's columns")
    ap.add_argument("--view", default="csv", choices=["csv"] + sorted(VIEWS),
                    help="how to render the CSV (default: as it is)")
    args = ap.parse_args()
    if args.view == "csv":
        lines = csv_as_markdown(args.csv, args.columns.split(",") if args.columns else None)
    elif args.columns:
        sys.exit("markdown_blocks.py: --columns applies to --view csv only")
    else:
        lines = VIEWS[args.view](args.csv)
    replace_block(args.doc, f"<!-- BEGIN GENERATED {args.name} -->",
                  f"<!-- END GENERATED {args.name} -->", lines)
    print("written", args.doc, f"({args.name})")


if __name__ == "__main__":
    main()
