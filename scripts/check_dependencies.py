#!/usr/bin/python3
"""The floors of docs/folders.md, checked on the #include lines of the sources.

Every folder with sources stands on a floor and includes only folders on its own floor or below:

  floor 1  the library: core materials layers frf loads convolution model contact stress surfaces
           validation distributed (and the umbrella header coatfft.hpp)
  floor 2  io/           file formats (npy, csv, input files, grid files, row slabs, NetCDF)
  floor 3  topography/   measured topographies
  floor 4  scene/        scene files: read, check, run, summarise
  floor 5  cli/ python/  the two front ends
  floor 6  bench/ tables/ tests/ fuzz/ examples/   programs built on all of it

Besides:
1. A folder with sources that has no floor is itself a broken rule: a new folder is placed here.
2. Neither front end includes the other: python/ nothing of cli/, cli/ nothing of python/.
3. The serial library includes nothing of distributed/ (built only with COATFFT_MPI); the
   umbrella header includes it under its own #if.
4. Kernels never include operators: nothing in convolution/fft/ or convolution/kernels/, and no
   library file whose name says kernel, influence or lattice, includes convolution/operators/ or
   any *_operator.hpp (an operator is built on kernels, not the reverse).

Prints each broken rule with its file and line; exits 1 when there is one.
Usage: check_dependencies.py [source root]   (default: the repository of this script)
"""
import fnmatch
import re
import sys
from pathlib import Path

SERIAL_LIBRARY = ["core", "materials", "layers", "frf", "loads", "convolution", "model",
                  "validation", "contact", "stress", "surfaces"]
FLOORS = {**{m: 1 for m in SERIAL_LIBRARY}, "distributed": 1, "coatfft.hpp": 1, "io": 2,
          "topography": 3, "scene": 4, "cli": 5, "python": 5,
          **{m: 6 for m in ["bench", "tables", "tests", "fuzz", "examples"]}}
SIDEWAYS = {"cli": ["python"], "python": ["cli"], **{m: ["distributed"] for m in SERIAL_LIBRARY}}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCE = re.compile(r"\.(cpp|hpp|h|cc)$")
SKIPPED = {"shared"}  # the workplace's inputs are not the project's


def skipped(root, name):
    """Hidden entries, the workplace's inputs, and the top-level folders .gitignore names
    (/build*/, /out*/: build trees and the examples' outputs) are not the project's sources."""
    if name.startswith(".") or name in SKIPPED:
        return True
    ignore = root / ".gitignore"
    patterns = [line.strip().strip("/") for line in ignore.read_text().splitlines()
                if line.startswith("/")] if ignore.exists() else []
    return any(fnmatch.fnmatch(name, pattern) for pattern in patterns)


def folder_of(include, source, root):
    """The top-level folder an include names: "cli/x.hpp", or "../cli/x.hpp" and "x.hpp" resolved
    from the including file."""
    first = include.split("/")[0]
    if first in FLOORS:
        return first
    target = (source.parent / include).resolve()
    return target.relative_to(root).parts[0] if root in target.parents else ""


def include_rules(top, source, root):
    """The broken rules of one source's include lines."""
    broken = []
    for number, line in enumerate(source.read_text().splitlines(), 1):
        match = INCLUDE.match(line)
        if not match:
            continue
        include = match.group(1)
        folder = folder_of(include, source, root)
        where = f"{source.relative_to(root)}:{number}"
        if folder in FLOORS and FLOORS[folder] > FLOORS[top]:
            broken.append(f"{where}: {top}/ (floor {FLOORS[top]}) must not include {folder}/ "
                          f"(floor {FLOORS[folder]}): {include}")
        if folder in SIDEWAYS.get(top, []):
            broken.append(f"{where}: {top}/ must not include {folder}/ ({include})")
        below = source.relative_to(root).parts[:2] in (("convolution", "fft"),
                                                      ("convolution", "kernels"))
        kernel = below or re.search(r"kernel|influence|lattice", source.name)
        operator = "operators/" in include or include.endswith("_operator.hpp")
        if top in SERIAL_LIBRARY and kernel and operator:
            broken.append(f"{where}: a kernel includes an operator ({include})")
    return broken


def main(root):
    broken = []
    for entry in sorted(root.iterdir()):
        if skipped(root, entry.name):
            continue
        sources = ([entry] if entry.is_file() and SOURCE.search(entry.name)
                   else sorted(p for p in entry.rglob("*") if SOURCE.search(p.name))
                   if entry.is_dir() else [])
        if not sources:
            continue
        if entry.name not in FLOORS:
            broken.append(f"{entry.name}: a folder with sources on no floor (scripts/"
                          "check_dependencies.py, docs/folders.md)")
            continue
        for source in sources:
            broken += include_rules(entry.name, source, root)
    for line in broken:
        print(line)
    print(f"check_dependencies: {len(broken)} broken rule(s)")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent.parent)
                  .resolve()))
