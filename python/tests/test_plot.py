"""python3 -m coatfft.plot OUTDIR: a picture for every kind of output folder, and its refusals."""
import os
import subprocess
import sys

import pytest

import coatfft.plot

GRID = '[grid]\nnx = 32\nny = 32\nlx = 3.0e-3\nly = 3.0e-3\n'
STEEL = '[substrate]\nmaterial = "steel"\n'
COATED = ('[substrate]\nmaterial = "steel"\n[[coating]]\nmaterial = "titanium_nitride"\n'
          'thickness = 5.0e-4\n')
HERTZ = '[pressure]\nkind = "hertz"\np0 = 1.0e9\na = 1.0e-3\n'
SPHERE = '[contact]\nindenter = "paraboloid"\nradius = 0.01\n'
SCENES = {
    # scene: the pictures its run gives
    "pressure": (GRID + STEEL + HERTZ, {"pressure.png", "uz.png"}),
    "contact": (GRID + STEEL + SPHERE + "load = 20.0\n", {"pressure.png", "gap.png"}),
    "stress": (GRID + COATED + HERTZ + '[stress]\ndepths = [1.0e-4, 3.0e-4]\nsection = "xz"\n'
               'depth_max = 1.0e-3\nnz = 4\nalpha = 4\n',
               {"pressure.png", "uz.png", "von_mises_planes.png", "von_mises_section.png"}),
    "sweep": (GRID.replace("ly = 3.0e-3\n", 'ly = 3.0e-3\nboundary = "periodic"\n') + STEEL
              + SPHERE + "load = [10.0, 20.0, 40.0]\n",
              {"pressure.png", "gap.png", "area_load.png"}),
}


def plot(*arguments):
    return subprocess.run([sys.executable, "-m", "coatfft.plot", *map(str, arguments)],
                          capture_output=True, text=True, timeout=120, env=os.environ.copy())


@pytest.mark.parametrize("kind", sorted(SCENES))
def test_every_kind_of_output_folder(coatfft_exe, tmp_path, kind):
    text, expected = SCENES[kind]
    scene = tmp_path / f"{kind}.toml"
    scene.write_text(text)
    out = tmp_path / "out"
    done = subprocess.run([coatfft_exe, "run", str(scene), "-o", str(out), "--quiet"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert coatfft.plot.main([str(out)]) == 0  # in process: matplotlib is imported once
    pictures = {p.name for p in (out / "plots").iterdir()}
    assert pictures == expected
    for name in pictures:
        assert (out / "plots" / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_as_a_program(coatfft_exe, tmp_path):
    scene = tmp_path / "contact.toml"
    scene.write_text(SCENES["contact"][0])
    out = tmp_path / "out"
    subprocess.run([coatfft_exe, "run", str(scene), "-o", str(out), "--quiet"], check=True)
    drawn = plot(out, "--to", tmp_path / "pictures", "--unit", "GPa")
    assert drawn.returncode == 0, drawn.stderr
    assert sorted(p.name for p in (tmp_path / "pictures").iterdir()) == ["gap.png", "pressure.png"]
    # Drawn again into the same folder: its own pictures are replaced.
    assert coatfft.plot.main([str(out), "--to", str(tmp_path / "pictures")]) == 0


def test_refusals(tmp_path, capsys):
    empty = tmp_path / "empty"
    empty.mkdir()
    assert coatfft.plot.main([str(empty)]) == 2
    error = capsys.readouterr().err
    assert error.count("\n") == 1 and "no summary.json" in error
    # A target folder holding something else than pictures is never written to.
    run = tmp_path / "run"
    run.mkdir()
    (run / "summary.json").write_text("{}")
    target = tmp_path / "mine"
    target.mkdir()
    (target / "notes.txt").write_text("keep")
    assert coatfft.plot.main([str(run), "--to", str(target)]) == 2
    assert "notes.txt" in capsys.readouterr().err
    assert (target / "notes.txt").read_text() == "keep"
    assert sorted(p.name for p in target.iterdir()) == ["notes.txt"]
