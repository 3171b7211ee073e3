#!/usr/bin/env python3
"""Writes the seed corpora of the libFuzzer targets into fuzz/corpus/<target>/.

Small valid inputs (and a few near misses) from which libFuzzer mutates: the example scenes and
scenes using every section and key, .npy files of every header version and layout the reader
accepts, and CSV files with comments, separators and the numbers' corner cases. Uses only the
standard library; rerun after changing it and commit the files it writes.
Usage: fuzz/make_corpus.py
"""
import pathlib
import shutil
import struct

ROOT = pathlib.Path(__file__).resolve().parent
REPO = ROOT.parent


def npy(major, header, values, pad=True):
    """A .npy file of format `major`.0: header dict text, then little-endian float64 values."""
    length_format = "<H" if major == 1 else "<I"
    preamble = 8 + struct.calcsize(length_format)
    if pad:
        header += " " * ((64 - (preamble + len(header) + 1) % 64) % 64) + "\n"
    data = b"".join(struct.pack("<d", v) for v in values)
    return (b"\x93NUMPY" + bytes([major, 0]) + struct.pack(length_format, len(header))
            + header.encode("latin-1") + data)


def npy_seeds():
    dict_ = "{{'descr': '<f8', 'fortran_order': False, 'shape': {}, }}"
    return {
        "1x1.npy": npy(1, dict_.format("(1, 1)"), [1.5]),
        "3x4.npy": npy(1, dict_.format("(3, 4)"), [0.25 * k for k in range(12)]),
        "2x3_special.npy": npy(1, dict_.format("(2, 3)"),
                               [0.0, -0.0, 5e-324, 1e308, float("inf"), float("nan")]),
        "v2.npy": npy(2, "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2)}",
                      [1, 2, 3, 4]),
        "v3_unpadded.npy": npy(3, '{"descr": "=f8", "fortran_order": False, "shape": ( 1 ,2 ,)}',
                               [7, 8], pad=False),
        "int_dtype.npy": npy(1, "{'descr': '<i4', 'fortran_order': False, 'shape': (2, 2), }",
                             [0, 0]),
        "fortran.npy": npy(1, "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 1), }",
                           [1, 2]),
        "vector.npy": npy(1, dict_.format("(3,)"), [1, 2, 3]),
    }


def csv_seeds():
    return {
        "plain.csv": "1,2,3\n4,5,6\n",
        "blanks_comments.csv": "# heights [m]\n1 2 3  # first row\n\n4\t5\t6\n",
        "semicolons_crlf.csv": "1;2;3\r\n4;5;6\r\n",
        "numbers.csv": "+1.5, -2.5e-3, 1e-400, 4.9e-324\ninf, -inf, nan, 1E+300\n",
        "single.csv": "42",
        "ragged.csv": "1, 2\n3\n",
        "word.csv": "1, x\n",
    }


def scene_seeds():
    grid = "[grid]\nnx = 4\nny = 3\nlx = 4.0e-3\nly = 3.0e-3\n\n"
    steel = '[substrate]\nmaterial = "steel"\n\n'
    return {
        "file_pressure.toml": grid + steel
        + '[pressure]\nkind = "file"\npath = "h.npy"\n\n[method]\nname = "direct"\n',
        "uniform_disk.toml": grid + "[substrate]\nE = 2.1e11\nnu = 0.3\n\n"
        + '[[coating]]\nE = 4e11\nnu = 0.25\nthickness = 1e-4\ninterface = "frictionless"\n\n'
        + '[[coating]]\nmaterial = "dlc"\nthickness = 2e-6\n\n'
        + '[pressure]\nkind = "uniform_disk"\np = 1e8\na = 1e-3\nsampling = "centre"\n\n'
        + '[method]\nname = "frf-dcfft"\nalpha = 2.0\ng0 = "quadrature"\ng0_tol = 1e-8\n'
        + 'planning = "estimate"\nthreads = 2\nwisdom = "w.fftw"\n',
        "height_map.toml": grid + steel
        + '[contact]\nindenter = "height_map"\npath = "h.csv"\napproach = 1e-7\n'
        + "tolerance = 1e-8\nmax_iterations = 50\n",
        "flat_punch.toml": grid + steel
        + '[contact]\nindenter = "flat_punch"\nradius = 1e-3\nedge_radius = 1e-4\n'
        + 'load = 10.0\nreport_approach = false\nindenter_material = "tungsten_carbide"\n',
        "cylinder.toml": grid + steel
        + '[contact]\nindenter = "cylinder"\nradius = 0.01\nlength = 1e-3\nend_radius = 0.02\n'
        + "load = 5.0\nindenter_E = 6e11\nindenter_nu = 0.22\n",
        "paraboloid.toml": grid + '[substrate]\nmaterial = "peek"\n\n'
        + '[[coating]]\nmaterial = "titanium_nitride"\nthickness = 1e-5\n\n'
        + '[contact]\nindenter = "paraboloid"\nradius = 0.05\nload = 1.0\n\n'
        + '[method]\nname = "frf-split"\n',
    }


def write(folder, files):
    target = ROOT / "corpus" / folder
    shutil.rmtree(target, ignore_errors=True)
    target.mkdir(parents=True)
    for name, content in files.items():
        data = content if isinstance(content, bytes) else content.encode()
        (target / name).write_bytes(data)


def main():
    scenes = scene_seeds()
    for example in sorted((REPO / "examples" / "scenes").glob("*.toml")):
        scenes["example_" + example.name] = example.read_bytes()
    write("fuzz_scene", scenes)
    write("fuzz_npy", npy_seeds())
    write("fuzz_csv", csv_seeds())


if __name__ == "__main__":
    main()
