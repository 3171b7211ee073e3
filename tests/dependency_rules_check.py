#!/usr/bin/python3
"""scripts/check_dependencies.py catches each kind of broken rule: planted in a small tree of
folders, every arrow running up a floor, sideways between the front ends or from the serial
library to distributed/, and a folder on no floor, is reported on its file and line; the same
tree without them passes."""
import subprocess
import sys
import tempfile
from pathlib import Path

CHECK = Path(__file__).resolve().parent.parent / "scripts" / "check_dependencies.py"
CLEAN = {"core/a.hpp": "", "io/npy.cpp": '#include "core/a.hpp"\n',
         "topography/t.cpp": '#include "io/npy.hpp"\n',
         "scene/s.cpp": '#include "topography/t.hpp"\n#include "io/npy.hpp"\n',
         "cli/c.cpp": '#include "scene/s.hpp"\n', "python/p.cpp": '#include "scene/s.hpp"\n',
         "tests/x.cpp": '#include "cli/c.hpp"\n#include "python/p.hpp"\n'}
BROKEN = {"io/up.cpp": '#include "topography/t.hpp"\n',        # floor 2 on floor 3
          "topography/up.cpp": '#include "scene/s.hpp"\n',     # floor 3 on floor 4
          "contact/up.cpp": '#include "io/npy.hpp"\n',         # the library on a file format
          "scene/up.cpp": '\n#include "../cli/c.hpp"\n',       # relative, floor 4 on floor 5
          "cli/side.cpp": '#include "python/p.hpp"\n',         # front end on front end
          "contact/mpi.cpp": '#include "distributed/d.hpp"\n', # serial library on distributed/
          "newfolder/n.cpp": ""}                               # a folder on no floor
EXPECTED = ["io/up.cpp:1", "topography/up.cpp:1", "contact/up.cpp:1", "scene/up.cpp:2",
            "cli/side.cpp:1", "contact/mpi.cpp:1", "newfolder: a folder with sources on no floor"]


def run(files):
    with tempfile.TemporaryDirectory() as root:
        for name, text in files.items():
            path = Path(root) / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        return subprocess.run([sys.executable, str(CHECK), root], capture_output=True, text=True)


clean = run(CLEAN)
assert clean.returncode == 0, clean.stdout
broken = run({**CLEAN, **BROKEN})
assert broken.returncode == 1, broken.stdout
for expected in EXPECTED:
    assert any(line.startswith(expected) for line in broken.stdout.splitlines()), \
        f"not reported: {expected}\n{broken.stdout}"
assert f"{len(EXPECTED)} broken rule(s)" in broken.stdout, broken.stdout
print(f"dependency_rules_check: {len(EXPECTED)} planted broken rules reported, a clean tree passes")
