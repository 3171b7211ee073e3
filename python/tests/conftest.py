"""Shared fixtures of the coatfft pytest suite.

ctest runs each test file with PYTHONPATH=build/python, COATFFT_EXE (the `coatfft` program, for
the comparisons with the command line) and COATFFT_SOURCE_DIR (examples/scenes, tests/data). Run
by hand, both fall back to paths relative to this file: the source tree two folders up and its
build/coatfft.
"""
import os
import pathlib
import warnings

import numpy as np
import pytest

import coatfft

HERE = pathlib.Path(__file__).resolve().parent
# Absolute: tests change the working directory (run_scene must write nothing there).
SOURCE_DIR = pathlib.Path(os.environ.get("COATFFT_SOURCE_DIR") or HERE.parents[1]).resolve()
SCENES = SOURCE_DIR / "examples" / "scenes"
EXE = pathlib.Path(os.environ.get("COATFFT_EXE") or SOURCE_DIR / "build" / "coatfft").resolve()


@pytest.fixture(scope="session")
def coatfft_exe():
    # A missing program fails the tests that need it rather than skipping them: a comparison that
    # silently does not run proves nothing.
    assert EXE.is_file() and os.access(EXE, os.X_OK), f"coatfft program not found at {EXE}"
    return str(EXE)


@pytest.fixture(scope="session")
def steel():
    return coatfft.material("steel")


@pytest.fixture(scope="session")
def tin():
    return coatfft.material("titanium_nitride")


@pytest.fixture(scope="session")
def tin_stack(steel, tin):
    """The body of examples/scenes/tin_2um.toml: 2 um of TiN bonded on steel."""
    return coatfft.LayerStack(steel, [coatfft.Coating(tin, 2e-6)])


def rel_max(a, b):
    """max |a - b| / max |b|: the error measure of every field comparison."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return float(np.abs(a - b).max() / np.abs(b).max())


def radius(grid):
    """Distance of every cell centre from the origin, shape (ny, nx)."""
    x, y = np.meshgrid(grid.x, grid.y)
    return np.hypot(x, y)


def quiet_operator(*args, **kwargs):
    """make_operator for the FRF pipelines at alpha = 2, whose predicted-error RuntimeWarning
    (tested in test_operator.py) is not what the calling test is about."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return coatfft.make_operator(*args, **kwargs)
