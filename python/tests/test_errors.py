"""Every error the module raises, with its message: ValueError for what the library refuses
(InvalidArgument, with its message), TypeError for arguments of the wrong type, and a UserFrf
function's own exceptions unchanged, from any thread. Then the threads: apply releases the GIL,
and one operator serves two Python threads at once."""
import re
import subprocess
import sys
import threading
import time
import warnings

import numpy as np
import pytest

import coatfft
from conftest import SCENES

STEEL = coatfft.material("steel")
TIN = coatfft.material("titanium_nitride")
STACK = coatfft.LayerStack(STEEL, [coatfft.Coating(TIN, 2e-6)])
GRID = coatfft.Grid(16, 8, 1e-3, 0.5e-3)
C0, C_INF = 2 / STEEL.E_star, 2 / TIN.E_star
WRONG_BODY = r"body: expected a LayerStack, a Material or an Frf \(UserFrf, TabulatedFrf\), not "


def builtin(k):
    return coatfft.frf(STACK, k)


def user(function=builtin):
    return coatfft.UserFrf(function, C0, C_INF)


def raises(exception, match, call):
    with pytest.raises(exception, match=match):
        call()


# --- bodies ---------------------------------------------------------------------------------

@pytest.mark.parametrize("e", [0.0, -1.0, float("nan"), float("inf")])
def test_material_bad_modulus(e):
    raises(ValueError, r"Material: E = .* Pa, but Young's modulus must be finite and > 0",
           lambda: coatfft.Material(e, 0.3))


@pytest.mark.parametrize("e", [1e-308, 1e-101, 1e101, 1e300])
def test_material_modulus_out_of_range(e):
    # E = 1e-308 once ended as "c0 = inf" deep inside a kernel: refused here, by name.
    raises(ValueError, r"Material: E = .* Pa, but Young's modulus must lie in \[1e-100, 1e\+?100\] Pa",
           lambda: coatfft.Material(e, 0.3))
    assert coatfft.Material(1e-100, 0.3).E == 1e-100 and coatfft.Material(1e100, 0.3).E == 1e100


@pytest.mark.parametrize("nu", [0.5, 0.49995, -1.0, -2.0, float("nan")])
def test_material_bad_poisson_ratio(nu):
    raises(ValueError, r"Poisson's ratio must be finite with -1 < nu <= 0.4999",
           lambda: coatfft.Material(1e9, nu))


def test_material_type_errors():
    raises(TypeError, "incompatible constructor arguments", lambda: coatfft.Material("a", 0.3))
    raises(TypeError, "incompatible function arguments", lambda: coatfft.material(3))


def test_unknown_material():
    raises(ValueError, r'unknown material "unobtainium" \(known: steel, .*titanium_nitride',
           lambda: coatfft.material("unobtainium"))


@pytest.mark.parametrize("thickness", [0.0, -1e-6, float("nan"), float("inf")])
def test_coating_bad_thickness(thickness):
    # Refused where it is written, at Coating().
    raises(ValueError, r"Coating: thickness = .* m, but it must be finite and > 0",
           lambda: coatfft.Coating(TIN, thickness))


def test_coating_and_stack_errors():
    raises(ValueError, r'Coating: interface = "glued" is not one of "bonded", "frictionless"',
           lambda: coatfft.Coating(TIN, 1e-6, "glued"))
    raises(TypeError, "incompatible constructor arguments", lambda: coatfft.Coating("tin", 1e-6))
    raises(ValueError, "LayerStack: 65 coatings, but at most 64 are allowed",
           lambda: coatfft.LayerStack(STEEL, [coatfft.Coating(TIN, 1e-6)] * 65))
    raises(TypeError, "incompatible constructor arguments", lambda: coatfft.LayerStack(1))
    raises(TypeError, "incompatible constructor arguments",
           lambda: coatfft.LayerStack(STEEL, [TIN]))


@pytest.mark.parametrize("k", [0.0, -1.0, float("nan"), float("inf")])
def test_frf_bad_wavenumber(k):
    raises(ValueError, r"frf: k = .* rad/m, but every wavenumber must be finite and > 0",
           lambda: coatfft.frf(STEEL, np.array([1.0, k])))
    table = coatfft.TabulatedFrf(np.logspace(0, 4, 9), 1 / np.logspace(0, 4, 9), c0=1, c_inf=1)
    raises(ValueError, "every wavenumber must be finite and > 0", lambda: table(np.array([k])))


def test_frf_type_errors():
    raises(TypeError, WRONG_BODY + "str", lambda: coatfft.frf("steel", np.ones(2)))
    raises(TypeError, WRONG_BODY + "Grid", lambda: coatfft.frf(GRID, np.ones(2)))
    raises(TypeError, "incompatible function arguments", lambda: coatfft.frf(STEEL, "abc"))


@pytest.mark.parametrize("c0, c_inf, name", [(0.0, 1.0, "c0"), (-1.0, 1.0, "c0"),
                                              (float("nan"), 1.0, "c0"), (1.0, 0.0, "c_inf"),
                                              (1.0, float("inf"), "c_inf")])
def test_user_frf_bad_limits(c0, c_inf, name):
    raises(ValueError, rf"UserFrf: {name} = .* 1/Pa, but it must be finite and > 0",
           lambda: coatfft.UserFrf(builtin, c0, c_inf))


def test_user_frf_not_callable():
    raises(TypeError, "incompatible constructor arguments", lambda: coatfft.UserFrf(3, C0, C_INF))
    raises(TypeError, "incompatible constructor arguments",
           lambda: coatfft.UserFrf(builtin, "1", C_INF))


class Compliance:
    """A callable object (not a function) is a valid UserFrf function."""

    def __call__(self, k):
        return builtin(k)


def test_user_frf_takes_any_callable():
    k = np.logspace(3, 7, 5)
    np.testing.assert_array_equal(user(Compliance())(k), builtin(k))


@pytest.mark.parametrize("result, type_name", [
    (lambda k: "x", r"str \(dtype <U1\)"),
    (lambda k: None, r"NoneType \(dtype object\)"),
    (lambda k: [None] * len(k), r"list \(dtype object\)"),
    (lambda k: k.astype(complex), r"ndarray \(dtype complex128\)"),
    (lambda k: np.full(k.shape, "1.0"), r"ndarray \(dtype <U3\)"),
    (lambda k: k > 0, r"ndarray \(dtype bool\)"),
])
def test_user_frf_returns_no_numbers(result, type_name):
    raises(TypeError, rf"UserFrf: the function returned {type_name}, not an array of real "
           r"numbers H", lambda: user(result)(np.ones(3)))


SHAPE = r"UserFrf: the function returned \d+ values in \d dimensions for \d+ wavenumbers; it " \
    r"must return one H per k"
VALUE = r"UserFrf: the function gives H\(.* rad/m\) = .* m/Pa, but H must be finite and > 0"


@pytest.mark.parametrize("result, message, generic", [
    (lambda k: builtin(k)[:-1], "returned 2 values in 1 dimensions for 3 wavenumbers", SHAPE),
    (lambda k: builtin(k).reshape(1, -1), "returned 3 values in 2 dimensions for 3", SHAPE),
    (lambda k: 1.0, "returned 1 values in 0 dimensions for 3 wavenumbers", SHAPE),
    (lambda k: -builtin(k), r"gives H\(1000 rad/m\) = -.* m/Pa, but H must be finite and > 0",
     VALUE),
    (lambda k: 0 * k, r"gives H\(1000 rad/m\) = 0 m/Pa", VALUE),
    (lambda k: np.where(k > 2e3, np.nan, builtin(k)), r"gives H\(10000 rad/m\) = nan m/Pa",
     VALUE),
    (lambda k: np.inf * k, r"gives H\(1000 rad/m\) = inf m/Pa", VALUE),
])
def test_user_frf_returns_bad_values(result, message, generic):
    raises(ValueError, "UserFrf: the function " + message,
           lambda: user(result)(np.array([1e3, 1e4, 1e5])))
    # The same error from inside an operator's setup, with its worker threads.
    raises(ValueError, generic,
           lambda: coatfft.make_operator(GRID, user(result), method="frf-split", threads=2))


def test_tabulated_frf_errors():
    k = np.logspace(0, 4, 9)
    h = 1 / k
    raises(ValueError, "TabulatedFrf: 3 rows, but a table needs at least 5",
           lambda: coatfft.TabulatedFrf(k[:3], h[:3], c0=1, c_inf=1))
    raises(ValueError, "TabulatedFrf: 9 values of k but 8 of H",
           lambda: coatfft.TabulatedFrf(k, h[:-1], c0=1, c_inf=1))
    raises(ValueError, r"TabulatedFrf: row 0: k = 0 rad/m, but it must be finite and > 0",
           lambda: coatfft.TabulatedFrf(np.r_[0, k[1:]], h, c0=1, c_inf=1))
    raises(ValueError, r"row 4: k = .* rad/m, but k must be strictly ascending",
           lambda: coatfft.TabulatedFrf(np.r_[k[:4], k[3], k[5:]], h, c0=1, c_inf=1))
    raises(ValueError, r"row 2: H = -1 m/Pa, but it must be finite and > 0",
           lambda: coatfft.TabulatedFrf(k, np.r_[h[:2], -1, h[3:]], c0=1, c_inf=1))
    raises(ValueError, r"c0 = -1 1/Pa, but it must be finite and > 0",
           lambda: coatfft.TabulatedFrf(k, h, c0=-1, c_inf=1))
    raises(ValueError, r"c_inf = nan 1/Pa, but it must be finite and > 0",
           lambda: coatfft.TabulatedFrf(k, h, c0=1, c_inf=float("nan")))
    # k H not flat at an end: the limit cannot be estimated from the table.
    steep = 1 / k * (1 + 1 / (1 + k))
    raises(ValueError, r"the table does not reach the small-k limit; extend it, or give c0",
           lambda: coatfft.TabulatedFrf(k, steep, c_inf=1))
    raises(ValueError, r"the table does not reach the large-k limit; extend it, or give c_inf",
           lambda: coatfft.TabulatedFrf(k, 1 / k * (1 + k / 1e4), c0=1))
    raises(TypeError, "incompatible constructor arguments",
           lambda: coatfft.TabulatedFrf("abc", h))


# --- grid and loads ---------------------------------------------------------------------------

@pytest.mark.parametrize("args, message", [
    ((0, 4, 1.0, 1.0), r"Grid: nx = 0, but nx must be in \[1, 65536\]"),
    ((4, -2, 1.0, 1.0), r"Grid: ny = -2, but ny must be in \[1, 65536\]"),
    # The program's limit per axis (coatfft run refuses nx = 65537 by the same constant).
    ((2**40, 8, 1.0, 1.0), r"Grid: nx = 1099511627776, but nx must be in \[1, 65536\]"),
    ((8, 65537, 1.0, 1.0), r"Grid: ny = 65537, but ny must be in \[1, 65536\]"),
    ((4, 4, 0.0, 1.0), "Grid: lx = 0 m, but lx must be finite and > 0"),
    ((4, 4, 1.0, float("inf")), "Grid: ly = inf m, but ly must be finite and > 0"),
    ((4, 4, float("nan"), 1.0), "Grid: lx = nan m"),
])
def test_bad_grid(args, message):
    raises(ValueError, message, lambda: coatfft.Grid(*args))


def test_grid_type_errors():
    raises(TypeError, "incompatible constructor arguments", lambda: coatfft.Grid(3.5, 4, 1, 1))
    raises(TypeError, "incompatible constructor arguments", lambda: coatfft.Grid(3, 4, "1", 1))


@pytest.mark.parametrize("function", [coatfft.hertz_pressure, coatfft.uniform_disk_pressure])
def test_pressure_errors(function):
    name = function.__name__
    raises(ValueError, r'sampling = "corner" is not one of "centre", "cell_average"',
           lambda: function(GRID, 1e9, 1e-4, "corner"))
    raises(ValueError, rf"{name}: p0? = nan Pa must be finite and > 0",
           lambda: function(GRID, float("nan"), 1e-4))
    raises(ValueError, rf"{name}: a = -1 m must be finite and > 0",
           lambda: function(GRID, 1e9, -1.0))
    raises(ValueError, rf"{name}: a = 0 m", lambda: function(GRID, 1e9, 0.0))
    raises(TypeError, "incompatible function arguments", lambda: function(GRID, "1e9", 1e-4))
    raises(TypeError, "incompatible function arguments", lambda: function(STEEL, 1e9, 1e-4))


@pytest.mark.parametrize("function", [coatfft.hertz_pressure, coatfft.uniform_disk_pressure])
def test_pressure_limits_as_the_program(function):
    # The scene reader's limits (loads/load_limits.hpp): GRID is 1 mm x 0.5 mm, dx = 62.5 um.
    name = function.__name__
    raises(ValueError, rf"{name}: p0? = -1e\+09 Pa must be finite and > 0",
           lambda: function(GRID, -1e9, 1e-4))
    raises(ValueError, rf"{name}: a = 3e-04 m .* at most half the domain \(0.00025 m\)",
           lambda: function(GRID, 1e9, 3e-4))
    raises(ValueError, rf"{name}: a = 1e-05 m: the load is narrower than a cell",
           lambda: function(GRID, 1e9, 1e-5))
    # Cell averages keep a sub-cell load's force: allowed, and the force is right.
    p = function(GRID, 1e9, 1e-5, "cell_average")
    force = p.sum() * GRID.dx * GRID.dy
    expected = (2.0 / 3.0 if name == "hertz_pressure" else 1.0) * np.pi * 1e-10 * 1e9
    assert abs(force - expected) <= 1e-12 * expected


def test_memory_refused_before_allocation():
    # 65536^2 cells: the padded dcfft lattice alone needs about 410 GB, beyond any CI machine.
    huge = coatfft.Grid(65536, 65536, 1e-3, 1e-3)
    raises(ValueError, r"make_operator needs about .* of memory, driven by grid 65536 x 65536 "
           r"\(131072 x 131072 transform lattice\), but .* is available: use fewer cells",
           lambda: coatfft.make_operator(huge, STEEL, method="dcfft"))
    raises(ValueError, r"make_operator needs about .* of memory",
           lambda: coatfft.make_operator(huge, STEEL))
    # np.zeros takes no memory until written, and is passed without a copy.
    big = coatfft.Grid(16384, 16384, 1e-3, 1e-3)
    p = np.zeros((16384, 16384))
    raises(ValueError, r"stresses needs about .* driven by grid 16384 x 16384, 512 planes",
           lambda: coatfft.stresses(STEEL, big, np.linspace(1e-5, 1e-4, 512), p))
    raises(ValueError, r"surface_displacements needs about .* driven by grid 16384 x 16384",
           lambda: coatfft.surface_displacements(STEEL, big, p))


def test_stress_depths_as_the_program():
    p = coatfft.hertz_pressure(GRID, 1e9, 1e-4)
    raises(ValueError, "stresses: depths must be a 1-D list of depths",
           lambda: coatfft.stresses(STEEL, GRID, [[1e-4, 2e-4]], p))
    raises(ValueError, "513 depths given; at most 512 planes",
           lambda: coatfft.stresses(STEEL, GRID, np.linspace(1e-5, 1e-4, 513), p))
    raises(ValueError, "depth z = 0 m: every depth must be finite and > 0",
           lambda: coatfft.stresses(STEEL, GRID, [0.0], p))


@pytest.mark.parametrize("function", [coatfft.hertz_displacement,
                                      coatfft.uniform_disk_displacement])
def test_closed_form_displacement_errors(function):
    name = function.__name__
    e = STEEL.E_star
    raises(ValueError, rf"{name}: r = -1 m, but r must be finite and >= 0",
           lambda: function(np.array([0.0, -1.0]), 1e9, 1e-3, e))
    raises(ValueError, rf"{name}: r = nan m", lambda: function([float("nan")], 1e9, 1e-3, e))
    raises(ValueError, rf"{name}: pressure = inf Pa, but it must be finite",
           lambda: function([0.0], float("inf"), 1e-3, e))
    raises(ValueError, rf"{name}: a = 0 m, but a must be finite and > 0",
           lambda: function([0.0], 1e9, 0.0, e))
    raises(ValueError, rf"{name}: E\* = -1 Pa, but E\* must be finite and > 0",
           lambda: function([0.0], 1e9, 1e-3, -1.0))
    raises(TypeError, "incompatible function arguments", lambda: function("r", 1e9, 1e-3, e))


def test_hankel_errors():
    r = np.array([0.0])
    raises(ValueError, r'load = "point" is not one of "hertz", "uniform_disk"',
           lambda: coatfft.hankel_displacement(STEEL, r, 1e9, 1e-3, load="point"))
    for rel_tol in (0.0, 1e-15, 0.01, float("nan")):
        raises(ValueError, r"hankel_displacement: rel_tol = .*, but it must lie in \[1e-14, 1e-2\)",
               lambda: coatfft.hankel_displacement(STEEL, r, 1e9, 1e-3, rel_tol=rel_tol))
    raises(ValueError, "hankel_displacement: a = -1 m, but a must be finite and > 0",
           lambda: coatfft.hankel_displacement(STACK, r, 1e9, -1.0))
    raises(ValueError, "hankel_displacement: r = -1 m, but r must be finite and >= 0",
           lambda: coatfft.hankel_displacement(STACK, np.array([-1.0]), 1e9, 1e-3))
    raises(ValueError, "hankel_displacement: amplitude = nan Pa, but it must be finite",
           lambda: coatfft.hankel_displacement(STACK, r, float("nan"), 1e-3))
    raises(TypeError, WRONG_BODY + "str", lambda: coatfft.hankel_displacement("x", r, 1e9, 1e-3))


# --- make_operator and apply --------------------------------------------------------------

def test_bad_method_name():
    raises(ValueError, r'make_operator: method = "fft" is not one of "direct", "dcfft", '
           r'"frf-spectral", "frf-dcfft", "frf-split" or "auto"',
           lambda: coatfft.make_operator(GRID, STEEL, method="fft"))


NAMED = ["direct", "dcfft", "frf-spectral", "frf-dcfft", "frf-split"]


@pytest.mark.parametrize("method", NAMED)
@pytest.mark.parametrize("keyword, value", [("tolerance", 1e-3), ("load_radius", 1e-4)])
def test_auto_keywords_refused_by_named_methods(method, keyword, value):
    body = STEEL if method in ("direct", "dcfft") else STACK
    raises(ValueError, rf'make_operator: {keyword}: applies only to method = "auto", not to '
           rf'method = "{method}"',
           lambda: coatfft.make_operator(GRID, body, method=method, **{keyword: value}))


@pytest.mark.parametrize("method", ["direct", "dcfft", "frf-split", "auto"])
@pytest.mark.parametrize("keyword, value", [("alpha", 2.0), ("g0", "quadrature"),
                                            ("g0_tol", 1e-8)])
def test_pipeline_keywords_refused_by_other_methods(method, keyword, value):
    body = STEEL if method in ("direct", "dcfft") else STACK
    chooses = r" \(which chooses them\)" if method == "auto" else ""
    # The one check of a scene's [method] keys and of these keywords (scene/method_request.hpp).
    raises(ValueError, rf'make_operator: {keyword}: applies only to the FRF pipelines '
           rf'"frf-spectral" and "frf-dcfft", not to method = "{method}"{chooses}',
           lambda: coatfft.make_operator(GRID, body, method=method, **{keyword: value}))


def test_option_values_refused():
    def make(body=STACK, **keywords):
        return lambda: coatfft.make_operator(GRID, body, **keywords)

    # Every message names the keyword as it is written in the call.
    raises(ValueError, r'make_operator: planning = "exhaustive" is not one of "estimate", "measure"',
           make(method="frf-split", planning="exhaustive"))
    raises(ValueError, r'make_operator: planning = "exhaustive" is not one of "estimate", "measure"',
           make(planning="exhaustive"))
    raises(ValueError,
           r'make_operator: g0 = "bogus" is not one of "regularized", "quadrature", "omitted"',
           make(method="frf-spectral", g0="bogus"))
    raises(ValueError, r"make_operator: g0_tol = 1 must be in \(0, 1\)",
           make(method="frf-dcfft", g0_tol=1.0))
    raises(ValueError, r"alpha = 0.5 must be >= 1", make(method="frf-spectral", alpha=0.5))
    raises(ValueError, r"alpha = nan must be >= 1", make(method="frf-spectral", alpha=np.nan))
    raises(ValueError, r"alpha = 1.1: alpha \* nx and alpha \* ny must be whole numbers of cells",
           make(method="frf-spectral", alpha=1.1))
    raises(ValueError, r"alpha = 1.5: frf-dcfft needs alpha >= 2",
           make(method="frf-dcfft", alpha=1.5))
    for threads in (0, 257):
        raises(ValueError, rf"make_operator: threads = {threads} must be in 1..256",
               make(method="frf-split", threads=threads))
        raises(ValueError, rf"make_operator: threads = {threads} must be in 1..256",
               make(threads=threads))
    for tolerance in (1e-13, 0.2):
        raises(ValueError, rf"make_operator: tolerance = {tolerance:g} must be in "
               r"\[1e-12, 0.1\]", make(tolerance=tolerance))
    for radius in (0.0, np.nan):
        raises(ValueError, r"make_operator: load_radius = .* m must be finite and > 0",
               make(load_radius=radius))
    # 200 m on a 0.5 mm domain: refused as the scene's [pressure] a is (one library check),
    # before the automatic choice starts.
    raises(ValueError, r"make_operator: load_radius = 200 m must be finite and > 0, and at most "
           r"half the domain \(0.00025 m\)", make(load_radius=200.0))
    for applications in (0.5, np.inf):
        raises(ValueError, r"make_operator: applications = .* must be finite and >= 1",
               make(applications=applications))


def test_keywords_that_do_not_apply_are_refused():
    # As a scene's [method]: a keyword the method does not use is refused, not ignored.
    for method in ("direct", "dcfft", "frf-split"):
        raises(ValueError, rf'make_operator: applications: applies only to method = "auto", not '
               rf'to method = "{method}"',
               lambda: coatfft.make_operator(GRID, STEEL, method=method, applications=100.0))
    raises(ValueError, r'make_operator: planning: FFTW settings do not apply to method = '
           r'"direct", which uses no FFT',
           lambda: coatfft.make_operator(GRID, STEEL, method="direct", planning="measure"))


def test_direct_is_limited_as_in_scenes(tmp_path):
    # One limit, the library's (check_operator_options), for Python's keywords and a scene alike.
    grid = coatfft.Grid(257, 256, 1e-3, 1e-3)  # 65792 cells > 65536
    limit = r"direct summation on 257 x 256 cells: it is limited to 65536 cells"
    raises(ValueError, limit, lambda: coatfft.make_operator(grid, STEEL, method="direct"))
    scene = tmp_path / "direct.toml"
    scene.write_text('[grid]\nnx = 257\nny = 256\nlx = 1e-3\nly = 1e-3\n[substrate]\n'
                     'material = "steel"\n[pressure]\nkind = "hertz"\np0 = 1e9\na = 2e-4\n'
                     '[method]\nname = "direct"\n')
    raises(ValueError, r"\[method\] " + limit, lambda: coatfft.run_scene(str(scene)))


def test_body_refused_by_the_method():
    for method in ("direct", "dcfft"):
        raises(ValueError, rf'method "{method}" uses Love\'s coefficients of a homogeneous '
               r'half-space; for a coated body use "frf-split"',
               lambda: coatfft.make_operator(GRID, STACK, method=method))
        raises(ValueError, rf'make_operator: method "{method}" uses Love\'s coefficients .*, '
               r"which an FRF alone does not give",
               lambda: coatfft.make_operator(GRID, user(), method=method))


def test_make_operator_type_errors():
    raises(TypeError, WRONG_BODY + "str", lambda: coatfft.make_operator(GRID, "steel"))
    raises(TypeError, WRONG_BODY + "list", lambda: coatfft.make_operator(GRID, [STEEL]))
    raises(TypeError, "incompatible function arguments", lambda: coatfft.make_operator(STEEL, GRID))
    # The options are keywords only.
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.make_operator(GRID, STEEL, "dcfft"))
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.make_operator(GRID, STEEL, method="dcfft", threads="2"))
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.make_operator(GRID, STEEL, tolerance="1e-3"))


OPERATOR = coatfft.make_operator(GRID, STEEL, method="dcfft")
PRESSURE = coatfft.hertz_pressure(GRID, 1e9, 1e-4)


@pytest.mark.parametrize("shape", [(16, 8), (8, 8), (128,), (8, 16, 1)])
def test_apply_wrong_shape(shape):
    wrong = np.zeros(shape)
    text = "(" + ", ".join(map(str, shape)) + ("," if len(shape) == 1 else "") + ")"
    raises(ValueError, re.escape(f"apply: pressure: shape {text}, but the grid needs (ny, nx) = "
                                 "(8, 16)"), lambda: OPERATOR.apply(wrong))


@pytest.mark.parametrize("value", [None, 0.0, np.zeros(())])
def test_apply_single_value(value):
    # numpy makes a 0-d array of each: the message names a single value, not a shape "()".
    raises(ValueError, re.escape("apply: pressure: got a single value (None or a number), but the "
                                 "grid needs an array of shape (ny, nx) = (8, 16)"),
           lambda: OPERATOR.apply(value))


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_apply_not_finite(bad):
    p = PRESSURE.copy()
    p[3, 5] = bad
    raises(ValueError, re.escape(f"apply: pressure[3, 5] = {bad} is not finite"),
           lambda: OPERATOR(p))


def test_apply_overflow_and_types():
    raises(ValueError, "apply: the displacement overflows double precision",
           lambda: OPERATOR(np.full(GRID.shape, 1e308)))
    raises(TypeError, "incompatible function arguments", lambda: OPERATOR("abc"))
    raises(TypeError, "incompatible function arguments", lambda: OPERATOR([[1, 2], [3]]))


# --- solve_contact --------------------------------------------------------------------------

HEIGHT = np.hypot(*np.meshgrid(GRID.x, GRID.y)) ** 2 / (2 * 0.01)


def test_contact_errors():
    raises(ValueError, r"solve_contact: give exactly one of load \[N\] and approach \[m\]",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT))
    raises(ValueError, r"solve_contact: give exactly one of load \[N\] and approach \[m\]",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, load=1.0, approach=1e-6))
    raises(ValueError, re.escape("solve_contact: height: shape (16, 8), but the grid needs "
                                 "(ny, nx) = (8, 16)"),
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT.T, load=1.0))
    h = HEIGHT.copy()
    h[0, 0] = np.nan
    raises(ValueError, re.escape("solve_contact: height[0, 0] = nan is not finite"),
           lambda: coatfft.solve_contact(OPERATOR, h, load=1.0))
    for load in (0.0, -1.0, np.nan):
        raises(ValueError, r"ContactSolver: load = .* N, but the total load must be finite and > 0",
               lambda: coatfft.solve_contact(OPERATOR, HEIGHT, load=load))
    raises(ValueError, r"ContactSolver: approach = nan m, but it must be finite",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, approach=np.nan))
    raises(ValueError, r"ContactSolver: approach = -1e-06 m, but it must exceed min\(height\)",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, approach=-1e-6))
    raises(ValueError, r"ContactSolver: tolerance = 0, but it must be finite and > 0",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, load=1.0, tolerance=0.0))
    raises(ValueError, r"ContactSolver: max_iterations = 0, but it must be >= 1",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, load=1.0, max_iterations=0))
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.solve_contact(PRESSURE, HEIGHT, load=1.0))
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, load="1"))
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.solve_contact(OPERATOR, HEIGHT, 1.0))


# --- scenes and validate_frf --------------------------------------------------------------

def cli_error(exe, scene, tmp_path):
    done = subprocess.run([exe, "run", str(scene), "-o", str(tmp_path / "out"), "--quiet"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and not (tmp_path / "out").exists()
    prefix = "coatfft: error: "
    assert done.stderr.startswith(prefix)
    return done.stderr[len(prefix):].strip()


def test_run_scene_missing_file(coatfft_exe, tmp_path):
    missing = tmp_path / "missing.toml"
    message = cli_error(coatfft_exe, missing, tmp_path)
    assert message == f"{missing}: cannot open: No such file or directory"
    with pytest.raises(ValueError) as error:
        coatfft.run_scene(str(missing))
    assert str(error.value) == message
    raises(ValueError, "not a regular file", lambda: coatfft.run_scene(str(tmp_path)))
    raises(TypeError, "incompatible function arguments", lambda: coatfft.run_scene(3))


@pytest.mark.parametrize("edit, message", [
    (lambda t: t.replace('name = "dcfft"', 'name = "dcfft"\nalpha = 3'),
     r'\[method\] alpha \(line \d+\): applies only to the FRF pipelines'),
    (lambda t: t.replace("nx = 65", "nx = 0"), r"nx"),
    (lambda t: t.replace('kind = "hertz"', 'kind = "cone"'), r"cone"),
    (lambda t: t + "\n[contact]\nindenter = \"sphere\"\nradius = 0.01\nload = 1.0\n",
     r"exactly one of \[pressure\] .* and \[contact\]"),
    (lambda t: t.replace("[grid]", "[grid"), r"."),
])
def test_run_scene_bad_scene_as_the_program(coatfft_exe, tmp_path, edit, message):
    scene = tmp_path / "bad.toml"
    scene.write_text(edit((SCENES / "hertz.toml").read_text()))
    expected = cli_error(coatfft_exe, scene, tmp_path)
    assert re.search(message, expected)
    # The same message, word for word, as a ValueError (accepted as a pathlib.Path too).
    for path in (str(scene), scene):
        with pytest.raises(ValueError) as error:
            coatfft.run_scene(path)
        assert str(error.value) == expected


def test_run_scene_contact_too_large_as_the_program(coatfft_exe, tmp_path):
    # A contact that reaches the domain's edge cannot be trusted: refused by both.
    scene = tmp_path / "edge.toml"
    scene.write_text((SCENES / "sphere_contact.toml").read_text().replace(
        "load = 100.0 ", "load = 1e5 "))
    expected = cli_error(coatfft_exe, scene, tmp_path)
    assert "the contact reaches the domain edge" in expected
    with pytest.raises(ValueError) as error:
        coatfft.run_scene(scene)
    assert str(error.value) == expected


def test_warnings_as_errors():
    # A warnings filter "error" turns the module's RuntimeWarnings into exceptions, cleanly.
    grid = coatfft.Grid(32, 32, 1e-3, 1e-3)
    scene = SCENES / "sphere_contact.toml"
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        raises(RuntimeWarning, "method frf-spectral: predicted error",
               lambda: coatfft.make_operator(grid, STEEL, method="frf-spectral"))
        raises(RuntimeWarning, "method frf-dcfft: predicted error",
               lambda: coatfft.make_operator(grid, STEEL, method="frf-dcfft"))
        assert coatfft.run_scene(scene)["summary"]["warnings"] == []  # nothing to warn about


def test_validate_frf_errors():
    for tolerance in (0.0, 1.0, -1e-6, np.nan):
        raises(ValueError, r"validate_frf: tolerance = .* must be in \(0, 1\)",
               lambda: coatfft.validate_frf(STACK, STACK, GRID, tolerance))
    raises(ValueError, r"validate_frf: body must be a LayerStack or a Material .*, not an Frf",
           lambda: coatfft.validate_frf(STACK, user(), GRID))
    raises(TypeError, WRONG_BODY.replace("body", "frf", 1) + "str",
           lambda: coatfft.validate_frf("x", STACK, GRID))
    raises(TypeError, WRONG_BODY + "int", lambda: coatfft.validate_frf(STACK, 3, GRID))
    raises(ValueError, r"validate_frf: give load and load_radius together",
           lambda: coatfft.validate_frf(STACK, STACK, GRID, load="hertz"))
    raises(ValueError, r"validate_frf: give load and load_radius together",
           lambda: coatfft.validate_frf(STACK, STACK, GRID, load_radius=1e-4))
    raises(ValueError, r'load = "cone" is not one of "hertz", "uniform_disk"',
           lambda: coatfft.validate_frf(STACK, STACK, GRID, load="cone", load_radius=1e-4))
    raises(ValueError, r'sampling = "corner" is not one of "centre", "cell_average"',
           lambda: coatfft.validate_frf(STACK, STACK, GRID, load="hertz", load_radius=1e-4,
                                        sampling="corner"))
    raises(TypeError, "incompatible function arguments",
           lambda: coatfft.validate_frf(STACK, STACK, "grid"))


# --- a UserFrf function that raises ---------------------------------------------------------

class FrfFailure(Exception):
    """The user's own exception type, with its own attribute."""

    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


def failing_after(calls):
    count = {"n": 0}

    def function(k):
        count["n"] += 1
        if count["n"] > calls:
            raise FrfFailure(f"boom at call {count['n']}", code=42)
        return builtin(k)

    return function


@pytest.mark.parametrize("method", ["frf-split", "frf-spectral", "frf-dcfft", "auto"])
@pytest.mark.parametrize("threads", [1, 2])
def test_function_exception_from_operator_setup(method, threads):
    grid = coatfft.Grid(64, 64, 0.8e-3, 0.8e-3)
    frf = user(failing_after(3))
    with pytest.raises(FrfFailure, match=r"boom at call \d+") as error:
        coatfft.make_operator(grid, frf, method=method, threads=threads)
    assert type(error.value) is FrfFailure and error.value.code == 42
    # Nothing is left held: the GIL, the workers. The next operator builds and works.
    op = coatfft.make_operator(grid, user(), method="frf-split", threads=threads)
    assert np.isfinite(op(coatfft.hertz_pressure(grid, 1e9, 1e-4))).all()


def test_function_exception_from_every_entry():
    frf = user(failing_after(0))
    for call in (lambda: frf(np.ones(3)), lambda: coatfft.frf(frf, np.ones(3)),
                 lambda: coatfft.hankel_displacement(frf, np.zeros(1), 1e9, 1e-3),
                 lambda: coatfft.validate_frf(frf, STACK, GRID),
                 lambda: coatfft.make_operator(GRID, frf, tolerance=1e-3)):
        with pytest.raises(FrfFailure, match="boom at call") as error:
            call()
        assert error.value.code == 42
    # KeyboardInterrupt-like exceptions too come out as they are.
    def interrupt(k):
        raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt):
        coatfft.make_operator(GRID, user(interrupt), method="frf-spectral", threads=2)


# --- threads ----------------------------------------------------------------------------------

BIG = coatfft.Grid(512, 512, 1e-3, 1e-3)


def moves_a_python_thread(call, tries=20):
    """Whether another Python thread runs while `call()` does: whether it releases the GIL.

    With a switch interval of 100 s the interpreter never takes the GIL from the main thread:
    the counter can move between the two reads below only if the call releases it. So a count
    that moves proves the release, whatever the machine's load; one that does not cannot happen
    with the release but for a scheduler starving the counting thread for all of a call (tens of
    ms), which the 20 tries make vanishingly rare. Measured: a builtin that holds the GIL
    (sum(range(2e6)), 10 ms) moves it in 0 of 20 tries, time.sleep(0.02) in 20 of 20."""
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1
            time.sleep(1e-5)  # lets the main thread take the GIL back at once after the call

    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    thread = threading.Thread(target=count)
    thread.start()
    try:
        while counter[0] == 0:
            time.sleep(1e-3)
        for _ in range(tries):
            before = counter[0]
            call()
            if counter[0] > before:
                return True
        return False
    finally:
        stop.set()
        thread.join()
        sys.setswitchinterval(interval)


def test_the_probe_sees_a_call_that_holds_the_gil():
    assert not moves_a_python_thread(lambda: sum(range(2_000_000)), tries=3)


BIG_OP = coatfft.make_operator(BIG, STEEL, method="dcfft")
BIG_P = coatfft.hertz_pressure(BIG, 1e9, 2e-4)
SMALL = coatfft.Grid(128, 128, 0.8e-3, 0.8e-3)
SMALL_OP = coatfft.make_operator(SMALL, STEEL, method="dcfft")
SPHERE = np.hypot(*np.meshgrid(SMALL.x, SMALL.y)) ** 2 / (2 * 0.01)


@pytest.mark.parametrize("call", [
    lambda: BIG_OP.apply(BIG_P),  # 18 ms at 512^2
    lambda: coatfft.solve_contact(SMALL_OP, SPHERE, load=100.0),
    lambda: coatfft.make_operator(SMALL, STACK, method="frf-split"),
    lambda: coatfft.make_operator(SMALL, STACK),
    lambda: coatfft.frf(STACK, np.logspace(0, 8, 300_000)),
    lambda: coatfft.hankel_displacement(STACK, np.array([0.0, 1e-4]), 1e9, 2e-4),
    lambda: coatfft.hertz_displacement(np.linspace(0, 1, 1_000_000), 1e9, 0.5, 1e11),
    lambda: coatfft.run_scene(SCENES / "tin_2um.toml"),
    lambda: coatfft.validate_frf(STACK, STACK, coatfft.Grid(32, 32, 0.3e-3, 0.3e-3)),
], ids=["apply", "solve_contact", "make_operator", "auto", "frf", "hankel_displacement",
        "hertz_displacement", "run_scene", "validate_frf"])
def test_long_calls_release_the_gil(call):
    assert moves_a_python_thread(call)


def test_one_operator_two_threads():
    grid = coatfft.Grid(256, 256, 0.8e-3, 0.8e-3)
    op = coatfft.make_operator(grid, STEEL, method="dcfft")
    loads = {"hertz": coatfft.hertz_pressure(grid, 1e9, 1e-4),
             "disk": coatfft.uniform_disk_pressure(grid, 3e8, 5e-5, "cell_average")}
    expected = {name: op(p) for name, p in loads.items()}
    height = np.hypot(*np.meshgrid(grid.x, grid.y)) ** 2 / (2 * 0.01)
    contact = coatfft.solve_contact(op, height, load=10.0)
    results, errors = {}, []
    barrier = threading.Barrier(3)

    def apply(name):
        try:
            barrier.wait()
            results[name] = [op.apply(loads[name]) for _ in range(30)]
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    def solve():
        try:
            barrier.wait()
            results["contact"] = [coatfft.solve_contact(op, height, load=10.0) for _ in range(3)]
        except Exception as e:  # pragma: no cover
            errors.append(e)

    threads = [threading.Thread(target=apply, args=(name,)) for name in loads]
    threads.append(threading.Thread(target=solve))
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    # Each thread its own right answer, bit for bit: the operator's mutex lets one apply (or one
    # contact solve) at a time use its buffers.
    for name in loads:
        assert len(results[name]) == 30
        for u in results[name]:
            np.testing.assert_array_equal(u, expected[name])
    for r in results["contact"]:
        np.testing.assert_array_equal(r.pressure, contact.pressure)
        assert r.approach == contact.approach and r.iterations == contact.iterations


def test_tabulated_frf_limits_that_contradict_the_table():
    k = np.logspace(0, 4, 9)
    h = 1 / k  # k H = 1 at both ends
    raises(ValueError, r"TabulatedFrf: c0 = 1e\+08 1/Pa and the table's k H = 1 1/Pa .* differ by "
           r"a factor 1e\+08, more than 10: they contradict each other",
           lambda: coatfft.TabulatedFrf(k, h, c0=1e8, c_inf=1))
    raises(ValueError, r"c_inf = 1e-08 1/Pa .* factor 1e\+08",
           lambda: coatfft.TabulatedFrf(k, h, c0=1, c_inf=1e-8))
    with pytest.warns(RuntimeWarning, match=r"c0 = 1.05 1/Pa .* differ by 5"):
        table = coatfft.TabulatedFrf(k, h, c0=1.05, c_inf=1)
    assert table.c0 == 1.05
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        coatfft.TabulatedFrf(k, h, c0=1.005, c_inf=1)


# --- grids too large for the machine --------------------------------------------------------

GRID_LIMITS = r"""
import resource, sys, time
import coatfft
# 2 GiB of address space: the checks must refuse before allocating, not run into the limit.
resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))
big = coatfft.Grid(65536, 65536, 1.0, 1.0)
wide = coatfft.Grid(32768, 2, 1.0, 1e-4)
calls = [
    ("self_affine_surface", lambda: coatfft.self_affine_surface(big, hurst=0.8, rms_height=1e-6)),
    ("sphere_height", lambda: coatfft.sphere_height(big, 0.5)),
    ("paraboloid_height", lambda: coatfft.paraboloid_height(big, 0.5)),
    ("hertz_pressure", lambda: coatfft.hertz_pressure(big, 1e9, 0.1)),
    ("uniform_disk_pressure", lambda: coatfft.uniform_disk_pressure(big, 1e9, 0.1)),
    # Small enough for the memory, too long a side for the program's limit.
    ("at most 16384 cells a side",
     lambda: coatfft.self_affine_surface(wide, hurst=0.8, rms_height=1e-6)),
]
for name, call in calls:
    start = time.monotonic()
    try:
        call()
        print(name, "returned")
    except ValueError as e:
        assert name in str(e), (name, str(e))
        print(name, "refused", round(time.monotonic() - start, 3))
"""


def test_grids_too_large_are_refused_before_allocating():
    # Under a 2 GiB address-space limit (which the memory check counts, as ulimit -v), every
    # function that returns an array on a grid refuses a 65536^2 grid (34 GB a field) with a
    # ValueError naming itself and at once: no MemoryError, no minutes of work.
    done = subprocess.run([sys.executable, "-c", GRID_LIMITS], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert len(lines) == 6, done.stdout
    for line in lines:
        name, verdict, seconds = line.rsplit(" ", 2)
        assert verdict == "refused", line
        assert float(seconds) < 1.0, line
