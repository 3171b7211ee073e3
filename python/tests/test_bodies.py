"""Materials, coatings, layer stacks and FRFs: Material, material, material_names, Coating,
LayerStack, frf, UserFrf, TabulatedFrf (their errors: test_errors.py)."""
import csv
import re
import subprocess

import numpy as np
import pytest

import coatfft
from conftest import SOURCE_DIR

# One rounding of a product or quotient, plus the rounding of the reference computed another way.
ROUND_OFF = 4e-16


def test_version(coatfft_exe):
    # The module is the library of the `coatfft` program: "coatfft 0.1.0" from --version.
    done = subprocess.run([coatfft_exe, "--version"], capture_output=True, text=True, timeout=30)
    assert done.stdout.split() == ["coatfft", coatfft.__version__]
    assert re.fullmatch(r"\d+\.\d+\.\d+", coatfft.__version__)


def test_material_properties():
    m = coatfft.Material(210e9, 0.3)
    assert m.E == 210e9 and m.nu == 0.3
    # E* = E / (1 - nu^2) and G = E / (2 (1 + nu)) (Johnson 1985): a few roundings apart.
    assert m.E_star == pytest.approx(210e9 / (1 - 0.09), rel=ROUND_OFF)
    assert m.shear_modulus == pytest.approx(210e9 / 2.6, rel=ROUND_OFF)
    auxetic = coatfft.Material(1e9, -0.5)
    assert auxetic.E_star == pytest.approx(1e9 / 0.75, rel=ROUND_OFF)
    assert auxetic.shear_modulus == pytest.approx(1e9, rel=ROUND_OFF)
    # nu = 0.4999 is the largest value accepted (frf/ refuses the incompressible limit).
    assert coatfft.Material(1e9, 0.4999).nu == 0.4999


def test_material_repr_and_equality():
    m = coatfft.Material(210e9, 0.3)
    assert repr(m) == "Material(E=210000000000.0, nu=0.3)"
    # repr is Python's: it evaluates back to an equal material, every bit kept.
    odd = coatfft.Material(1.0 / 3.0 * 1e9, 0.1 + 0.2)
    assert eval(repr(odd), {"Material": coatfft.Material}) == odd
    assert m == coatfft.Material(210e9, 0.3)
    assert not (m != coatfft.Material(210e9, 0.3))
    assert m != coatfft.Material(210e9 * (1 + 2e-16), 0.3)
    assert m != coatfft.Material(210e9, 0.29)
    # Another type is simply unequal, as for any Python value (no TypeError).
    assert m != 3 and not (m == "steel") and m != None  # noqa: E711
    assert m in [1, "steel", m]


def test_catalogue():
    names = coatfft.material_names()
    assert isinstance(names, list) and len(names) == len(set(names))
    assert {"steel", "titanium_nitride"} <= set(names)
    # The values the example scenes state: steel 210 GPa, 0.30; TiN 400 GPa, 0.25.
    assert coatfft.material("steel") == coatfft.Material(210e9, 0.3)
    assert coatfft.material("titanium_nitride") == coatfft.Material(400e9, 0.25)
    for name in names:
        m = coatfft.material(name)
        assert isinstance(m, coatfft.Material)
        assert m.E > 0 and -1 < m.nu <= 0.4999


def test_coating_properties(tin):
    c = coatfft.Coating(tin, 2e-6)
    assert c.material == tin and c.thickness == 2e-6 and c.interface == "bonded"
    f = coatfft.Coating(material=tin, thickness=1e-3, interface="frictionless")
    assert f.interface == "frictionless" and f.thickness == 1e-3


def test_coating_repr_and_equality(tin, steel):
    c = coatfft.Coating(tin, 2e-6)
    assert c == coatfft.Coating(tin, 2e-6, "bonded")
    assert c != coatfft.Coating(tin, 2e-6, "frictionless")
    assert c != coatfft.Coating(tin, 3e-6)
    assert c != coatfft.Coating(steel, 2e-6)
    assert c != tin
    env = {"Coating": coatfft.Coating, "Material": coatfft.Material}
    assert eval(repr(c), env) == c
    assert "frictionless" in repr(coatfft.Coating(tin, 1e-6, "frictionless"))


def test_layer_stack_properties(steel, tin):
    half_space = coatfft.LayerStack(steel)
    assert half_space.substrate == steel and half_space.coatings == []
    assert half_space.is_homogeneous and half_space.total_thickness == 0.0
    dlc = coatfft.material("dlc")
    top, middle = coatfft.Coating(dlc, 1.5e-6), coatfft.Coating(tin, 2.5e-6, "frictionless")
    stack = coatfft.LayerStack(steel, [top, middle])
    assert not stack.is_homogeneous
    assert stack.coatings == [top, middle]  # top first, as given
    assert stack.total_thickness == pytest.approx(4e-6, rel=ROUND_OFF)
    assert stack.coatings[1].interface == "frictionless"


def test_layer_stack_repr_and_equality(steel, tin):
    stack = coatfft.LayerStack(steel, [coatfft.Coating(tin, 2e-6)])
    assert stack == coatfft.LayerStack(steel, [coatfft.Coating(tin, 2e-6)])
    assert stack != coatfft.LayerStack(steel)
    assert stack != coatfft.LayerStack(tin, [coatfft.Coating(tin, 2e-6)])
    assert stack != steel
    env = {"LayerStack": coatfft.LayerStack, "Coating": coatfft.Coating,
           "Material": coatfft.Material}
    assert eval(repr(stack), env) == stack
    assert eval(repr(coatfft.LayerStack(steel)), env) == coatfft.LayerStack(steel)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4), (2, 3, 5)])
def test_frf_of_material_is_boussinesq(steel, shape):
    rng = np.random.default_rng(1)
    k = 10.0 ** rng.uniform(-2, 9, size=shape)
    h = coatfft.frf(steel, k)
    assert isinstance(h, np.ndarray) and h.shape == k.shape and h.dtype == np.float64
    # H = 2 / (E* k) (Boussinesq; docs/frf.md): one division apart from the library's.
    np.testing.assert_allclose(h, 2.0 / (steel.E_star * k), rtol=ROUND_OFF, atol=0)
    # A homogeneous LayerStack is the same body.
    np.testing.assert_array_equal(coatfft.frf(coatfft.LayerStack(steel), k), h)


def test_frf_converts_its_input(steel):
    k = np.logspace(0, 8, 24).reshape(4, 6)
    h = coatfft.frf(steel, k)
    # Non-contiguous views, other dtypes and lists give what their float64 copy gives.
    np.testing.assert_array_equal(coatfft.frf(steel, k.T), h.T)
    np.testing.assert_array_equal(coatfft.frf(steel, k[:, ::2]), h[:, ::2])
    np.testing.assert_array_equal(coatfft.frf(steel, k.tolist()), h)
    k32 = k.astype(np.float32)
    np.testing.assert_array_equal(coatfft.frf(steel, k32), coatfft.frf(steel, k32.astype(float)))
    np.testing.assert_array_equal(coatfft.frf(steel, np.arange(1, 5)),
                                  coatfft.frf(steel, np.arange(1.0, 5.0)))
    assert coatfft.frf(steel, 1e3).shape == ()
    assert coatfft.frf(steel, np.empty(0)).shape == (0,)


def test_frf_of_coated_bodies_against_40_digit_table():
    # tests/data/frf_values.csv: 168 rows of C = H E1* k / 2 for one coating (bonded and
    # frictionless, E1/E2 and nu over wide ranges, kh 1e-6 .. 200), to 40 digits (docs/frf.md).
    # The documented target is 1e-12 for every row (measured worst: 4.4e-16).
    rows = list(csv.DictReader(open(SOURCE_DIR / "tests" / "data" / "frf_values.csv")))
    assert len(rows) == 168
    worst = 0.0
    for row in rows:
        coating = coatfft.Material(float(row["E1"]), float(row["nu1"]))
        substrate = coatfft.Material(float(row["E2"]), float(row["nu2"]))
        stack = coatfft.LayerStack(substrate, [coatfft.Coating(coating, 1.0, row["interface"])])
        t = float(row["t"])  # k h with h = 1 m
        c = coatfft.frf(stack, np.array([t]))[0] * coating.E_star * t / 2
        worst = max(worst, abs(c / float(row["C"]) - 1))
    assert worst <= 1e-12


def test_frf_of_coated_body_limits_and_identities(steel, tin, tin_stack):
    h = 2e-6
    # k H -> 2/E*_substrate as k -> 0, with a first-order term O(k h): measured -0.25 k h, so the
    # bound |k H E*_sub/2 - 1| <= k h holds with a factor 4 to spare.
    for kh in (1e-9, 1e-7):
        k = np.array([kh / h])
        assert abs(k[0] * coatfft.frf(tin_stack, k)[0] * steel.E_star / 2 - 1) <= kh
    # k H -> 2/E*_top as k -> oo; the coating's effect decays like exp(-2 k h): nil at k h = 100.
    k = np.array([100 / h, 1000 / h])
    np.testing.assert_allclose(k * coatfft.frf(tin_stack, k), 2 / tin.E_star, rtol=ROUND_OFF)

    k = np.logspace(-3, 3, 61) / h
    # A bonded coating of the substrate's own material is no coating (multilayer recursion and
    # closed forms agree to 1.1e-14, docs/frf.md; 1e-13 leaves a factor 9; measured 2.2e-16).
    same = coatfft.LayerStack(steel, [coatfft.Coating(steel, h)])
    np.testing.assert_allclose(coatfft.frf(same, k), 2 / (steel.E_star * k), rtol=1e-13)
    # Two bonded TiN layers of 1 um (the multilayer recursion) are one of 2 um (closed form C1;
    # measured 5.6e-16).
    two = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-6), coatfft.Coating(tin, 1e-6)])
    np.testing.assert_allclose(coatfft.frf(two, k), coatfft.frf(tin_stack, k), rtol=1e-13)
    # A thick coating is the coating's half-space wherever k h >> 1.
    thick = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1.0)])
    k = np.array([1e3, 1e5])
    np.testing.assert_allclose(coatfft.frf(thick, k), 2 / (tin.E_star * k), rtol=ROUND_OFF)


def test_user_frf(steel):
    seen = []

    def boussinesq(k):
        seen.append(k.copy())
        return 2.0 / (steel.E_star * k)

    c0 = 2 / steel.E_star
    user = coatfft.UserFrf(boussinesq, c0, 0.5 * c0)
    assert isinstance(user, coatfft.Frf)
    assert user.c0 == c0 and user.c_inf == 0.5 * c0 and user.name == "user"
    assert user.function is boussinesq and user.calls == 0
    k = np.logspace(0, 6, 12).reshape(3, 4)
    # One call for the whole array, which the function sees as float64, 1-D and contiguous.
    h = user(k)
    assert user.calls == 1 and len(seen) == 1
    assert seen[0].dtype == np.float64 and seen[0].ndim == 1 and seen[0].flags.c_contiguous
    np.testing.assert_array_equal(seen[0], k.ravel())
    assert h.shape == (3, 4)
    np.testing.assert_array_equal(h, 2.0 / (steel.E_star * k))
    # frf() of a UserFrf is the same call.
    np.testing.assert_array_equal(coatfft.frf(user, k), h)
    assert user.calls == 2
    # A function may return a list, or integers: converted like any input.
    listed = coatfft.UserFrf(lambda k: [1] * len(k), 1.0, 1.0)
    np.testing.assert_array_equal(listed(np.ones(3)), np.ones(3))


def table_of(stack, per_decade, h=2e-6):
    """coatfft's own FRF of `stack` at `per_decade` log-spaced points over k h = 1e-8 .. 1e3."""
    k = np.logspace(-8, 3, 11 * per_decade + 1) / h
    return k, coatfft.frf(stack, k)


def midpoints(k):
    return np.sqrt(k[1:] * k[:-1])  # furthest from the table's points in ln k


def test_tabulated_frf_reproduces_its_table(steel, tin, tin_stack):
    k, h = table_of(tin_stack, 20)
    table = coatfft.TabulatedFrf(k, h)
    assert isinstance(table, coatfft.Frf) and table.name == "table"
    # At its points the spline returns its data: k H then H, two roundings.
    np.testing.assert_allclose(table(k), h, rtol=ROUND_OFF)
    # Between them: docs/frf.md documents at most 5.9e-5 (relative) at 20 points per decade over
    # coatfft's layered FRFs (measured here: 1.5e-6).
    km = midpoints(k)
    err20 = np.abs(table(km) / coatfft.frf(tin_stack, km) - 1).max()
    assert err20 <= 5.9e-5
    # Fourth order in the spacing of ln k: twice the points, 16 times less (measured 16.3); 12
    # allows for the error's dependence on where the extremum falls.
    k40, h40 = table_of(tin_stack, 40)
    km40 = midpoints(k40)
    err40 = np.abs(coatfft.TabulatedFrf(k40, h40)(km40) / coatfft.frf(tin_stack, km40) - 1).max()
    assert err40 <= 3.3e-6 and err20 / err40 >= 12
    # The ends are flat (k h = 1e-8 and 1e3): c0 and c_inf estimated from the end values, which
    # are within flatness_tolerance / 9 = 1.1e-7 of 2/E* (measured 2.5e-9 and 0).
    assert table.c0_estimated and table.c_inf_estimated
    assert table.c0 == pytest.approx(2 / steel.E_star, rel=1.1e-7)
    assert table.c_inf == pytest.approx(2 / tin.E_star, rel=1.1e-7)


def test_tabulated_frf_extensions(steel, tin, tin_stack):
    k, h = table_of(tin_stack, 10)
    c0, c_inf = 2 / steel.E_star, 2 / tin.E_star
    table = coatfft.TabulatedFrf(k, h, c0=c0, c_inf=c_inf)
    assert table.c0 == c0 and table.c_inf == c_inf
    assert not table.c0_estimated and not table.c_inf_estimated
    # Outside the table k H goes to its limits as tabulated_frf.hpp documents (a few roundings):
    # below, linearly in k; above, exponentially in k / k_max.
    k_min, k_max = k[0], k[-1]
    below = np.array([0.1 * k_min, 0.5 * k_min])
    expected = (c0 + (k_min * h[0] - c0) * below / k_min) / below
    np.testing.assert_allclose(table(below), expected, rtol=1e-15)
    above = np.array([2 * k_max, 10 * k_max])
    expected = (c_inf + (k_max * h[-1] - c_inf) * np.exp(1 - above / k_max)) / above
    np.testing.assert_allclose(table(above), expected, rtol=1e-15)
    # As a body: frf() of the table is the table.
    np.testing.assert_array_equal(coatfft.frf(table, k), table(k))
