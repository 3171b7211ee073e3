"""solve_contact and ContactResult against the Hertz solution of a sphere on a half-space
(Johnson 1985, section 4.2), and on a coated body between its two bare bounds (errors:
test_errors.py)."""
import numpy as np
import pytest

import coatfft
from conftest import SCENES, quiet_operator, radius, rel_max

# The scene of examples/scenes/sphere_contact.toml: R = 10 mm, W = 100 N on steel, 128^2 cells
# over [-0.4 mm, 0.4 mm]^2, so a = 0.148 mm spans 23.7 cells.
R, W = 0.01, 100.0
GRID = coatfft.Grid(128, 128, 0.8e-3, 0.8e-3)
HEIGHT = radius(GRID) ** 2 / (2 * R)  # the paraboloid of the sphere
STATUSES = {"converged", "iteration_limit", "pressure_vanished", "non_positive_curvature",
            "coupling_limit"}


def hertz(e_star, load=W):
    """Contact radius, peak pressure and approach of a sphere (Johnson eqs. 4.22-4.23)."""
    a = (3 * load * R / (4 * e_star)) ** (1 / 3)
    return a, 3 * load / (2 * np.pi * a * a), a * a / R


@pytest.fixture(scope="module")
def dcfft(steel):
    return coatfft.make_operator(GRID, steel, method="dcfft")


@pytest.fixture(scope="module")
def load_control(dcfft):
    return coatfft.solve_contact(dcfft, HEIGHT, load=W)


def check_consistent(result, op, height):
    """What every converged result satisfies, whatever the body."""
    assert result.status == "converged" and result.converged and result.warning == ""
    assert result.residual <= 1e-10 and result.iterations >= 1
    # One application per iteration, two in those that changed the contact set, one for a start.
    assert result.iterations <= result.operator_applications <= 2 * result.iterations + 1
    assert not result.touches_boundary
    for field in (result.pressure, result.displacement, result.gap):
        assert field.shape == GRID.shape and field.dtype == np.float64
        assert field.flags.c_contiguous and field.flags.writeable
    p = result.pressure
    assert np.all(p >= 0) and result.max_pressure == p.max()
    # The fields belong together: u is the operator's displacement of p, the gap h + u - approach
    # (both measured: identical).
    assert rel_max(result.displacement, op(p)) <= 1e-14
    gap = height + result.displacement - result.approach
    np.testing.assert_allclose(result.gap, gap, rtol=0, atol=1e-14 * result.approach)
    # Complementarity: no gap where there is pressure (measured 1.3e-13 of the approach: the
    # solver's tolerance 1e-10 on the pressure), no interpenetration elsewhere.
    in_contact = p > 0
    assert np.abs(result.gap[in_contact]).max() <= 1e-9 * result.approach
    assert result.gap[~in_contact].min() >= 0
    # Load and area are the sums over the cells in contact; the radius that of the same disk.
    assert result.load == pytest.approx(p.sum() * GRID.dx * GRID.dy, rel=1e-14)
    assert result.contact_area == np.count_nonzero(in_contact) * GRID.dx * GRID.dy
    assert result.contact_radius == pytest.approx(np.sqrt(result.contact_area / np.pi), rel=1e-15)


def test_hertz_under_load(steel, dcfft, load_control):
    r = load_control
    check_consistent(r, dcfft, HEIGHT)
    a, p0, approach = hertz(steel.E_star)
    # The load is imposed: exact to the solver's rescaling, round-off (measured 4.4e-15).
    assert r.load == pytest.approx(W, rel=1e-12)
    # The contact edge is resolved to the cell: the area counts the cells whose centre is in
    # contact, so the equivalent radius is within about half a cell of a (dx/a = 4.2 %; measured
    # +0.66 %, a sixth of a cell).
    assert abs(r.contact_radius - a) <= 0.5 * GRID.dx
    # Peak pressure and approach: the displacement's discretisation error at a/dx = 23.7 (the
    # operator test's 2.5e-3 of u(0) at 16 cells, falling as dx^1.5: 1.4e-3); measured -3.8e-4
    # and -8.7e-5. Bound 2e-3.
    assert r.max_pressure == pytest.approx(p0, rel=2e-3)
    assert r.approach == pytest.approx(approach, rel=2e-3)
    # The pressure is Hertz's p0 sqrt(1 - r^2/a^2) inside, away from the edge the cells blur:
    # measured 8.9e-5 (r < 0.5a) and 2.4e-4 (r < 0.8a) of p0.
    rr = radius(GRID)
    exact = p0 * np.sqrt(np.clip(1 - (rr / a) ** 2, 0, None))
    assert np.abs(r.pressure - exact)[rr < 0.5 * a].max() <= 1e-3 * p0
    assert np.abs(r.pressure - exact)[rr < 0.8 * a].max() <= 2e-3 * p0


def test_hertz_under_approach(steel, dcfft):
    a, p0, approach = hertz(steel.E_star)
    r = coatfft.solve_contact(dcfft, HEIGHT, approach=approach)
    check_consistent(r, dcfft, HEIGHT)
    assert r.approach == approach  # imposed
    # The load that approach needs: the discretisation error as above (measured +1.3e-4).
    assert r.load == pytest.approx(W, rel=2e-3)
    assert abs(r.contact_radius - a) <= 0.5 * GRID.dx
    assert r.max_pressure == pytest.approx(p0, rel=2e-3)


def test_sphere_height_is_the_paraboloid_near_the_axis(steel, dcfft, load_control):
    # The exact sphere R - sqrt(R^2 - r^2) differs from r^2/2R by r^4/8R^3 (2.7e-5 of the
    # approach at the contact edge, more beyond): the solutions agree to that order (measured
    # 2.5e-4 of p0, 1.5e-5 of the approach).
    sphere = R - np.sqrt(R * R - radius(GRID) ** 2)
    r = coatfft.solve_contact(dcfft, sphere, load=W)
    check_consistent(r, dcfft, sphere)
    assert rel_max(r.pressure, load_control.pressure) <= 1e-3
    assert r.approach == pytest.approx(load_control.approach, rel=1e-3)


def test_options_of_the_solver(dcfft, load_control):
    # Without the preconditioner: more iterations, the same solution to the tolerance (measured
    # 55 iterations against 29, 4.7e-10 of p0 apart).
    plain = coatfft.solve_contact(dcfft, HEIGHT, load=W, preconditioned=False)
    assert plain.status == "converged"
    assert plain.iterations > load_control.iterations
    assert rel_max(plain.pressure, load_control.pressure) <= 1e-8
    # A looser tolerance stops earlier, with a residual under it.
    loose = coatfft.solve_contact(dcfft, HEIGHT, load=W, tolerance=1e-6)
    assert loose.converged and loose.residual <= 1e-6
    assert loose.iterations < load_control.iterations
    assert rel_max(loose.pressure, load_control.pressure) <= 1e-4


def test_status_strings(dcfft, load_control):
    assert load_control.status in STATUSES
    # Too few iterations: not converged, and the warning says so.
    r = coatfft.solve_contact(dcfft, HEIGHT, load=W, max_iterations=3)
    assert r.status == "iteration_limit" and not r.converged and r.iterations == 3
    assert r.residual > 1e-10
    assert r.warning.startswith("not converged after 3 iterations")
    # Pressure on the border: too large a load for the domain.
    r = coatfft.solve_contact(dcfft, HEIGHT, load=1e4)
    assert r.touches_boundary and r.status in STATUSES
    assert "domain edge" in r.warning and "too small" in r.warning
    border = np.concatenate([r.pressure[0], r.pressure[-1], r.pressure[:, 0], r.pressure[:, -1]])
    assert border.max() > 0


def test_exactly_one_of_load_and_approach(dcfft):
    with pytest.raises(ValueError, match="exactly one of load"):
        coatfft.solve_contact(dcfft, HEIGHT)
    with pytest.raises(ValueError, match="exactly one of load"):
        coatfft.solve_contact(dcfft, HEIGHT, load=W, approach=1e-6)


def test_same_contact_through_an_frf(steel, load_control):
    # Steel as a UserFrf, by frf-split: the same body by another operator (its kernel to 1e-10
    # against Love's coefficients), the same contact (measured 2.1e-14 of p0).
    e_star = steel.E_star
    user = coatfft.UserFrf(lambda k: 2 / (e_star * k), 2 / e_star, 2 / e_star)
    op = coatfft.make_operator(GRID, user, method="frf-split")
    r = coatfft.solve_contact(op, HEIGHT, load=W)
    check_consistent(r, op, HEIGHT)
    assert rel_max(r.pressure, load_control.pressure) <= 1e-8
    assert r.approach == pytest.approx(load_control.approach, rel=1e-8)


def test_coated_contact_between_its_bare_bounds(steel, tin):
    stack = coatfft.LayerStack(steel, [coatfft.Coating(tin, 20e-6)])
    op = coatfft.make_operator(GRID, stack, method="frf-split")
    r = coatfft.solve_contact(op, HEIGHT, load=W)
    check_consistent(r, op, HEIGHT)
    assert r.load == pytest.approx(W, rel=1e-12)
    # A stiffer coating (h = 0.14 a) makes the contact smaller and the pressure higher than on
    # bare steel, but not as much as bare TiN would (computed: 0.1431 mm between 0.1207 mm and
    # 0.1481 mm).
    a_steel, p0_steel, d_steel = hertz(steel.E_star)
    a_tin, p0_tin, d_tin = hertz(tin.E_star)
    assert a_tin < r.contact_radius < a_steel
    assert p0_steel < r.max_pressure < p0_tin
    assert d_tin < r.approach < d_steel


def test_contact_without_g0(steel, load_control):
    # g0 = "omitted": the displacement's level is unknown, so under load control the approach
    # is not reported, while the pressure is that of an operator with g(0) (the offset does not
    # change a load-controlled contact; measured 4.1e-14 of p0).
    op = quiet_operator(GRID, steel, method="frf-spectral", g0="omitted")
    with_g0 = quiet_operator(GRID, steel, method="frf-spectral")
    r = coatfft.solve_contact(op, HEIGHT, load=W)
    reference = coatfft.solve_contact(with_g0, HEIGHT, load=W)
    assert r.approach is None and reference.approach is not None
    assert r.status == "converged" and r.load == pytest.approx(W, rel=1e-12)
    assert rel_max(r.pressure, reference.pressure) <= 1e-8
    # Under approach control it is refused rather than solved against a wrong level.
    with pytest.raises(ValueError, match='approach control needs .* g0 = "omitted"'):
        coatfft.solve_contact(op, HEIGHT, approach=load_control.approach)


def rough_gap(n, length, hurst, rms, seed):
    """A periodic random-phase self-affine gap (min 0): C(q) ~ q^(-2(1+H)) up to Nyquist."""
    rng = np.random.default_rng(seed)
    q = 2 * np.pi * np.hypot(*np.meshgrid(np.fft.fftfreq(n, length / n),
                                          np.fft.fftfreq(n, length / n), indexing="ij"))
    amplitude = np.where(q > 0, np.maximum(q, 1e-30) ** (-(1 + hurst)), 0.0)
    z = np.fft.ifft2(amplitude * np.exp(2j * np.pi * rng.random((n, n)))).real
    z *= rms / z.std()
    return z.max() - z


def test_light_rough_contact_converges_only_on_a_solution(steel):
    # A free 64^2 rough gap at 0.03 N: the solver once stopped at one iteration with one cell in
    # contact while others overlapped. Every converged result must satisfy complementarity on
    # every cell of the gap recomputed here from a fresh application, g = h + K p - approach:
    # eps = 1e-10 max|u| (the tolerance's displacement) + 64 ulps of the largest term.
    grid = coatfft.Grid(64, 64, 0.5e-3, 0.5e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    for seed in range(3):
        h = rough_gap(64, 0.5e-3, 0.8, 0.2e-6, seed)
        for load in (0.003, 0.03, 0.3):
            r = coatfft.solve_contact(op, h, load=load)
            assert r.converged
            u = op(r.pressure)
            contact = r.pressure > 0
            approach = (h + u)[contact].mean()
            g = h + u - approach
            eps = 1e-10 * np.abs(u).max() + 64 * np.finfo(float).eps * (
                np.abs(h).max() + np.abs(u).max() + abs(approach))
            assert g[~contact].min() >= -eps
            assert np.abs(g[contact]).max() <= eps
            assert 0 <= r.max_penetration <= eps
            assert r.max_penetration == max(0.0, -r.gap.min())


def test_a_two_thread_operator_solves_the_same_contact(steel):
    # The solve on an operator runs on the operator's threads (its preconditioner's transforms):
    # the same contact as on one thread, to the sums' order (1e-9 of the largest pressure: ten
    # times the tolerance's pressure change, 1e-10, and far below any contact's detail).
    grid = coatfft.Grid(128, 128, 0.5e-3, 0.5e-3)
    h = rough_gap(128, 0.5e-3, 0.8, 0.2e-6, 5)
    one, two = (coatfft.solve_contact(
        coatfft.make_operator(grid, steel, method="dcfft", boundary="periodic", threads=t),
        h, load=0.3) for t in (1, 2))
    assert one.converged and two.converged
    assert one.iterations == two.iterations
    assert np.abs(two.pressure - one.pressure).max() <= 1e-9 * one.pressure.max()


def test_extreme_loads_give_finite_fields(dcfft):
    # The problem is homogeneous: heights and load scaled by c scale the solution by c. At
    # c = 1e195 and 1e-290 the solver's inner products would leave double's range unscaled (they
    # once came back as NaN arrays); the fields must match c times the 100 N solution.
    reference = coatfft.solve_contact(dcfft, HEIGHT, load=W)
    for c in (1e195, 1e-290):
        r = coatfft.solve_contact(dcfft, HEIGHT * c, load=W * c)
        assert r.converged
        assert np.isfinite(r.pressure).all() and np.isfinite(r.gap).all()
        assert rel_max(r.pressure, reference.pressure * c) <= 1e-12
        assert r.load == pytest.approx(W * c, rel=1e-12)


def test_sliding_equals_the_program(tmp_path, steel, tin):
    # The example scene's sliding rough contact on a 64^2 crop of its gap (a period of its own):
    # solve_sliding on the periodic operator gives run_scene's pressure, and its
    # friction_coupling the summary's, to rounding.
    scene_gap = np.load(SCENES / "rough_coated_gap.npy")[:64, :64]
    gap = scene_gap - scene_gap.min()
    np.save(tmp_path / "gap.npy", gap)
    text = (
        "[grid]\nnx = 64\nny = 64\nlx = 0.25e-3\nly = 0.25e-3\nboundary = \"periodic\"\n"
        "[substrate]\nmaterial = \"steel\"\n[[coating]]\nmaterial = \"titanium_nitride\"\n"
        "thickness = 1e-5\n[method]\nname = \"frf-split\"\n[contact]\nindenter = \"height_map\"\n"
        "path = \"gap.npy\"\nload = 3.0\nfriction = 0.3\n")
    (tmp_path / "sliding.toml").write_text(text)
    run = coatfft.run_scene(str(tmp_path / "sliding.toml"))
    grid = coatfft.Grid(64, 64, 0.25e-3, 0.25e-3)
    body = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-5)])
    op = coatfft.make_operator(grid, body, method="frf-split", boundary="periodic")
    r = coatfft.solve_sliding(op, gap, body, friction=0.3, load=3.0)
    assert r.converged and r.friction_coupling["converged"]
    assert r.friction_coupling["solves"] == run["summary"]["friction_coupling"]["solves"]
    np.testing.assert_allclose(r.pressure, run["pressure"], rtol=0,
                               atol=1e-12 * run["pressure"].max())
    frictionless = coatfft.solve_contact(op, gap, load=3.0)
    assert frictionless.friction_coupling is None
    shift = np.abs(r.pressure - frictionless.pressure).max() / frictionless.pressure.max()
    assert shift == pytest.approx(r.friction_coupling["pressure_shift"], rel=1e-12)


def test_sliding_errors(steel, tin, dcfft):
    grid = dcfft.grid
    h = np.zeros(grid.shape)
    with pytest.raises(ValueError, match="exactly one"):
        coatfft.solve_sliding(dcfft, h, steel, friction=0.3)
    with pytest.raises(ValueError, match="friction"):
        coatfft.solve_sliding(dcfft, h, steel, friction=-1.0, load=1.0)
    sliding = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-4, "frictionless")])
    op = coatfft.make_operator(grid, sliding, method="frf-split")
    with pytest.raises(ValueError, match="frictionless"):
        coatfft.solve_sliding(op, h, sliding, friction=0.3, load=1.0)


def test_sliding_refuses_another_body(steel, tin):
    # The operator's body and the tractions' must be one body: a titanium-nitride coating's
    # operator with a bare steel body (or another thickness) gave a result of no body at all.
    grid = coatfft.Grid(32, 32, 0.25e-3, 0.25e-3)
    coated = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-5)])
    op = coatfft.make_operator(grid, coated, method="frf-split", boundary="periodic")
    h = np.zeros(grid.shape)
    for other in (steel, coatfft.LayerStack(steel, [coatfft.Coating(tin, 1.01e-5)]),
                  coatfft.LayerStack(tin, [coatfft.Coating(steel, 1e-5)])):
        with pytest.raises(ValueError, match="not the body the operator was made for"):
            coatfft.solve_sliding(op, h, other, friction=0.3, load=1.0)
    # The same body, built anew, is accepted.
    same = coatfft.LayerStack(steel, [coatfft.Coating(tin, 1e-5)])
    h = ((np.arange(32)[None, :] - 16.0) ** 2 + (np.arange(32)[:, None] - 16.0) ** 2) * 1e-9
    assert coatfft.solve_sliding(op, h, same, friction=0.3, load=1.0).converged
