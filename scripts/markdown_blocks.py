#!/usr/bin/python3
"""Generated blocks in the docs: a benchmark CSV rendered as a markdown table between markers.

    scripts/markdown_blocks.py DOC.md NAME FILE.csv [--columns c1,c2,...]

replaces the lines between `<!-- BEGIN GENERATED NAME -->` and `<!-- END GENERATED NAME -->` of
DOC.md (which must already hold both markers: a doc names where its numbers go) with the CSV's
`# key = value` headers as a list and its rows as a table, so that the numbers quoted in the docs
are the ones last measured. scripts/plot_pareto.py uses the same functions for its block.
"""
import argparse
import sys


def csv_as_markdown(path, columns=None):
    """The CSV's comment lines (verbatim, in a code block) then its rows as a markdown table."""
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if line.strip()]
    comments = [line for line in lines if line.startswith("#")]
    comments = ["```"] + comments + ["```"] if comments else []
    data = [line.split(",") for line in lines if not line.startswith("#")]
    if not data:
        return comments
    keep = range(len(data[0]))
    if columns:
        missing = [c for c in columns if c not in data[0]]
        if missing:
            sys.exit(f"markdown_blocks.py: {path} has no column(s) {', '.join(missing)}")
        keep = [data[0].index(c) for c in columns]
    rows = [[d[i] if i < len(d) else "" for i in keep] for d in data]
    out = ["| " + " | ".join(rows[0]) + " |", "|" + "---|" * len(rows[0])]
    out += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    return comments + [""] + out


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
    args = ap.parse_args()
    columns = args.columns.split(",") if args.columns else None
    replace_block(args.doc, f"<!-- BEGIN GENERATED {args.name} -->",
                  f"<!-- END GENERATED {args.name} -->", csv_as_markdown(args.csv, columns))
    print("written", args.doc, f"({args.name})")


if __name__ == "__main__":
    main()
