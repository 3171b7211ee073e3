#!/usr/bin/python3
"""The dependency rules of docs/architecture.md, checked on the #include lines of the sources.

1. The library's modules include no front end: nothing of scene/, cli/, python/, bench/, tables/
   or tests/.
2. The scene layer (scene/) includes nothing of cli/ or python/: both front ends stand on it.
3. Neither front end includes the other: python/ nothing of cli/, cli/ nothing of python/.
4. Kernels never include operators: nothing in convolution/fft/ or convolution/kernels/, and no
   library file whose name says kernel, influence or lattice, includes convolution/operators/ or
   any *_operator.hpp (an operator is built on kernels, not the reverse).

Prints each broken rule with its file and line; exits 1 when there is one.
Usage: check_dependencies.py [source root]   (default: the repository of this script)
"""
import re
import sys
from pathlib import Path

LIBRARY = ["core", "materials", "layers", "frf", "loads", "convolution", "model", "validation",
           "contact", "stress", "surfaces"]
FRONT = ["scene", "cli", "python", "bench", "tables", "tests"]
FORBIDDEN = {**{m: FRONT for m in LIBRARY}, "scene": ["cli", "python"], "python": ["cli"],
             "cli": ["python"]}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def folder_of(include, source, root):
    """The top-level folder an include names: "cli/x.hpp", or "../cli/x.hpp" and "x.hpp" resolved
    from the including file."""
    first = include.split("/")[0]
    if first in LIBRARY + FRONT:
        return first
    target = (source.parent / include).resolve()
    return target.relative_to(root).parts[0] if root in target.parents else ""


def main(root):
    broken = []
    for top, forbidden in FORBIDDEN.items():
        for source in sorted((root / top).rglob("*.[ch]pp")):
            for number, line in enumerate(source.read_text().splitlines(), 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                include = match.group(1)
                folder = folder_of(include, source, root)
                where = f"{source.relative_to(root)}:{number}"
                if folder in forbidden:
                    broken.append(f"{where}: {top}/ must not include {folder}/ ({include})")
                below = source.relative_to(root).parts[:2] in (("convolution", "fft"),
                                                              ("convolution", "kernels"))
                kernel = below or re.search(r"kernel|influence|lattice", source.name)
                operator = "operators/" in include or include.endswith("_operator.hpp")
                if top in LIBRARY and kernel and operator:
                    broken.append(f"{where}: a kernel includes an operator ({include})")
    for line in broken:
        print(line)
    print(f"check_dependencies: {len(broken)} broken rule(s)")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent.parent)
                  .resolve()))
