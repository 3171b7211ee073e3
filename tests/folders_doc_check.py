#!/usr/bin/python3
"""docs/folders.md against the tree: its table "Folders with sources" names every top-level
folder with sources, on the floor scripts/check_dependencies.py gives it, and no other; its table
"Other folders" names every other top-level folder (hidden ones may be named) and only folders
that exist; and it names every public header (each one listed by coatfft_public_headers(...) in
a CMakeLists.txt, as <coatfft/FOLDER/HEADER>) and no other. Build trees (build*) are skipped, as
check_dependencies.py skips them.

Prints each difference on one line; exits 1 when there is one.
Usage: folders_doc_check.py [source root]   (default: the repository of this script)
"""
import importlib.util
import re
import sys
from pathlib import Path

ROW = re.compile(r"^\|\s*`([^`/]+)/`\s*\|\s*([^|]*?)\s*\|")
HEADER = re.compile(r"<(coatfft/[^>\s]+)>")
PUBLIC_HEADERS = re.compile(r"coatfft_public_headers\(([^)]*)\)")


def load_rules(root):
    """scripts/check_dependencies.py as a module: its floors and what it counts as sources."""
    spec = importlib.util.spec_from_file_location("check_dependencies",
                                                  root / "scripts" / "check_dependencies.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def top_folders(root, rules):
    """The project's top-level folders (not the hidden ones, build trees or the workplace's)."""
    return {entry.name for entry in root.iterdir()
            if entry.is_dir() and not rules.skipped(root, entry.name)}


def folders_with_sources(root, rules):
    """The top-level folders holding a source file, as check_dependencies.py counts them."""
    return {name for name in top_folders(root, rules)
            if any(rules.SOURCE.search(p.name) for p in (root / name).rglob("*"))}


def public_headers(root, rules):
    """Every header named by coatfft_public_headers(...), as users include it."""
    headers = set()
    folders = [root / name for name in top_folders(root, rules)]
    cmakes = [root / "CMakeLists.txt"] + [c for f in folders for c in f.rglob("CMakeLists.txt")]
    for cmake in cmakes:
        relative = cmake.parent.relative_to(root)
        text = "\n".join(line.split("#")[0] for line in cmake.read_text().splitlines())
        for match in PUBLIC_HEADERS.finditer(text):
            prefix = "/".join(("coatfft",) + relative.parts)
            headers.update(f"{prefix}/{name}" for name in match.group(1).split())
    return headers


def table_rows(page, heading):
    """{folder: second cell} of the table under `## heading`."""
    section = page.split(f"\n## {heading}\n", 1)
    if len(section) < 2:
        return None
    rows = {}
    for line in section[1].split("\n## ", 1)[0].splitlines():
        match = ROW.match(line)
        if match:
            rows[match.group(1)] = match.group(2)
    return rows


def differences(root):
    rules = load_rules(root)
    page = (root / "docs" / "folders.md").read_text()
    found = []
    named = table_rows(page, "Folders with sources")
    others = table_rows(page, "Other folders")
    if named is None or others is None:
        return ["docs/folders.md: no section \"## Folders with sources\" or \"## Other folders\""]
    actual = folders_with_sources(root, rules)
    found += [f"docs/folders.md misses the folder with sources {f}/"
              for f in sorted(actual - set(named))]
    found += [f"docs/folders.md names {f}/ among the folders with sources, which has none"
              for f in sorted(set(named) - actual)]
    found += [f"docs/folders.md puts {f}/ on floor {named[f]}, check_dependencies.py on "
              f"{rules.FLOORS.get(f)}" for f in sorted(actual & set(named))
              if named[f] != str(rules.FLOORS.get(f))]
    found += [f"docs/folders.md names the folder {f}/, which does not exist"
              for f in sorted(others) if not (root / f).is_dir()]
    found += [f"docs/folders.md misses the folder {f}/ (a row of \"Other folders\")"
              for f in sorted(top_folders(root, rules) - actual - set(others))]
    headers = public_headers(root, rules)
    on_page = set(HEADER.findall(page))
    found += [f"docs/folders.md misses the public header <{h}>" for h in sorted(headers - on_page)]
    found += [f"docs/folders.md names <{h}>, which no coatfft_public_headers lists"
              for h in sorted(on_page - headers)]
    return found


def main(arguments):
    root = Path(arguments[1]) if len(arguments) > 1 else Path(__file__).parent.parent
    found = differences(root.resolve())
    print("\n".join(found + [f"folders_doc_check: {len(found)} difference(s)"]))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
