"""make_operator and Operator: each method against closed forms, the Hankel reference and an
independent direct sum; UserFrf against the built-in FRF; the keywords; the arrays in and out
(errors: test_errors.py)."""
import gc
import warnings

import numpy as np
import pytest

import coatfft
from conftest import quiet_operator, radius, rel_max

P0, A = 1e9, 1e-3  # the Hertz load of examples/scenes/hertz.toml


def hertz_grid(cells_per_radius):
    """[-2a, 2a]^2 with a = cells_per_radius cells: no cell centre at r = 0 (even count)."""
    n = 4 * cells_per_radius
    return coatfft.Grid(n, n, 4 * A, 4 * A)


def hertz_error(grid, steel):
    p = coatfft.hertz_pressure(grid, P0, A)
    u = coatfft.make_operator(grid, steel, method="dcfft").apply(p)
    exact = coatfft.hertz_displacement(radius(grid), P0, A, steel.E_star)
    return np.abs(u - exact).max() / (np.pi * P0 * A / (2 * steel.E_star))


def test_dcfft_hertz_on_steel_against_closed_form(steel):
    # max |u - u_Hertz| / u(0) over every cell centre, Love's DC-FFT of the centre-sampled Hertz
    # pressure. DC-FFT is exact for the piecewise-constant pressure, so what remains is the
    # sampling's error: measured 2.47e-3 at a = 16 cells, 8.1e-4
    # at 32 cells and 6.8e-3 at 8 (order 1.5: the sqrt edge of the Hertz pressure). The bound
    # 3e-3 is the measurement plus 20 %, well under the 6.8e-3 one refinement coarser.
    e16 = hertz_error(hertz_grid(16), steel)
    assert e16 <= 3e-3
    # It is a discretisation error: it falls with the cell, by 2^1.5 = 2.8 per halving (measured
    # 3.06); at least 2.5.
    e32 = hertz_error(hertz_grid(32), steel)
    assert e16 / e32 >= 2.5


def test_dcfft_equals_direct(steel):
    grid = hertz_grid(16)
    p = coatfft.hertz_pressure(grid, P0, A)
    dcfft = coatfft.make_operator(grid, steel, method="dcfft")
    direct = coatfft.make_operator(grid, steel, method="direct")
    assert dcfft.method == "dcfft" and direct.method == "direct"
    # The same sum of the same Love coefficients, once by FFTs of 128^2 points: round-off only
    # (measured 3.2e-15 of max |u|; 1e-13 is 30 eps log2(128^2)).
    assert rel_max(dcfft(p), direct(p)) <= 1e-13


def love_matrix(grid, e_star):
    """Influence matrix (ny nx)^2 of a half-space, C order: u at cell centres of unit pressure on
    each cell, from the integral of 1/rho over the rectangle (Love 1929; Johnson eq. 3.25),
    written with asinh, which has no cancellation: F(s, t) = s asinh(t/|s|) + t asinh(s/|t|)."""
    x, y = np.meshgrid(grid.x, grid.y)
    x, y = x.ravel(), y.ravel()
    s = x[None, :] - x[:, None]  # source minus field point
    t = y[None, :] - y[:, None]

    def f(s, t):
        return s * np.arcsinh(t / np.abs(s)) + t * np.arcsinh(s / np.abs(t))

    hx, hy = grid.dx / 2, grid.dy / 2
    integral = f(s + hx, t + hy) - f(s - hx, t + hy) - f(s + hx, t - hy) + f(s - hx, t - hy)
    return integral / (np.pi * e_star)


def test_love_methods_against_independent_direct_sum(steel):
    # A small non-square grid of non-square cells with an arbitrary pressure: the direct sum of
    # numpy's matrix-vector product is a reference independent of the library's code. Its far
    # coefficients lose up to (r/dx)^2 ~ 200 eps in the corner sum; 1e-13 of max |u| covers it
    # (measured: 1.4e-15 for both).
    grid = coatfft.Grid(13, 9, 1.3e-3, 0.6e-3)
    rng = np.random.default_rng(7)
    p = rng.uniform(0, 1e8, size=grid.shape)
    reference = (love_matrix(grid, steel.E_star) @ p.ravel()).reshape(grid.shape)
    for method in ("direct", "dcfft"):
        op = coatfft.make_operator(grid, steel, method=method)
        assert rel_max(op(p), reference) <= 1e-13


def frf_split_centre_error(stack, cells_per_radius):
    """Relative error at r = 0 of frf-split's displacement of the cell-averaged Hertz load of
    tin_2um.toml (p0 = 2 GPa, a = 0.2 mm) against the continuous Hankel reference. Odd n puts a
    cell centre on r = 0; the domain is [-2a, 2a]^2 as tin_2um's [-1.5a, 1.5a]^2 or wider."""
    p0, a = 2e9, 0.2e-3
    n = 4 * cells_per_radius + 1
    dx = a / cells_per_radius
    grid = coatfft.Grid(n, n, n * dx, n * dx)
    assert grid.x[n // 2] == 0 and grid.y[n // 2] == 0
    p = coatfft.hertz_pressure(grid, p0, a, "cell_average")
    u = coatfft.make_operator(grid, stack, method="frf-split").apply(p)
    exact = coatfft.hankel_displacement(stack, np.array([0.0]), p0, a)[0]
    return (u[n // 2, n // 2] - exact) / exact


def test_frf_split_coated_against_hankel(tin_stack):
    # frf-split is exact for the cell forces (its kernel to 1e-10); the difference from the
    # continuous load's Hankel integral is the cell-average sampling, second order in dx:
    # measured -2.53e-3 (a = 8 cells), -6.43e-4 (16), -1.62e-4 (32), -4.06e-5 (64). At
    # dx = a/32 the bound is 2.5e-4 (the measurement + 50 %, under the 6.4e-4 of a/16).
    e32 = frf_split_centre_error(tin_stack, 32)
    assert abs(e32) <= 2.5e-4
    # Second order: halving the cell divides it by 4 (measured 3.97); [3.5, 4.5].
    e16 = frf_split_centre_error(tin_stack, 16)
    assert 3.5 <= e16 / e32 <= 4.5


def wrapped(stack):
    """A UserFrf that is the built-in FRF of `stack`, and a counter of the wavenumbers asked."""
    asked = {"k": 0}

    def function(k):
        asked["k"] += k.size
        return coatfft.frf(stack, k)

    top = stack.coatings[0].material if stack.coatings else stack.substrate
    user = coatfft.UserFrf(function, 2 / stack.substrate.E_star, 2 / top.E_star)
    return user, asked


@pytest.mark.parametrize("method", ["frf-split", "frf-spectral", "frf-dcfft", "auto"])
def test_user_frf_gives_the_built_in_displacement(tin_stack, method):
    grid = coatfft.Grid(64, 64, 0.8e-3, 0.8e-3)
    p = coatfft.hertz_pressure(grid, 2e9, 0.2e-3, "cell_average")
    user, asked = wrapped(tin_stack)
    by_user = quiet_operator(grid, user, method=method)
    built_in = quiet_operator(grid, tin_stack, method=method)
    assert by_user.report["frf"] == "user" and built_in.report["frf"] == "coated_bonded"
    assert by_user.method == built_in.method
    # The same H at the same wavenumbers, in batches rather than one by one: the results are
    # those of the built-in FRF (measured: identical, difference 0); 1e-10 would still allow a
    # different order of the same sums.
    assert rel_max(by_user(p), built_in(p)) <= 1e-10
    # Batches: a few hundred calls for tens of thousands of wavenumbers (measured 13 calls /
    # 14487 k for frf-split, 264 / 12344 for the pipelines, 21 / 20063 for auto).
    assert user.calls < 300 and asked["k"] > 10000
    assert asked["k"] / user.calls > 40


def test_user_frf_calls_are_batches_for_frf_spectral(tin_stack):
    grid = coatfft.Grid(64, 64, 0.8e-3, 0.8e-3)
    user, asked = wrapped(tin_stack)
    quiet_operator(grid, user, method="frf-spectral")
    # 128 lattice columns at alpha = 2 plus g(0)'s adaptive quadrature: 264 calls (measured) for
    # 12344 wavenumbers, where one call per point would be thousands.
    assert user.calls < 300 and asked["k"] >= 128 * 65


@pytest.mark.parametrize("method", ["frf-spectral", "frf-dcfft"])
def test_pipelines_warn_and_predict_their_error(steel, method):
    grid = coatfft.Grid(64, 64, 0.8e-3, 0.8e-3)
    p = coatfft.hertz_pressure(grid, P0, 0.2e-3)
    exact = coatfft.make_operator(grid, steel, method="direct")(p)
    errors = {}
    for alpha in (2, 4):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            op = coatfft.make_operator(grid, steel, method=method, alpha=alpha)
        report = op.report
        assert report["alpha"] == alpha
        # frf-spectral transforms the alpha-extended lattice; frf-dcfft samples it, then runs
        # DC-FFT's padded 2n lattice.
        assert report["fft_nx"] == (alpha * 64 if method == "frf-spectral" else 128)
        error = rel_max(op(p), exact)
        # The periodisation error is predicted (docs/theory.md 4.6) for a reference Hertz load;
        # ours is one, a = L/4. Measured prediction/error: 1.30 (alpha 2), 1.29 (alpha 4): the
        # prediction bounds the error and is within a factor 3 of it.
        assert error <= report["predicted_error"] <= 3 * error
        errors[alpha] = error
        # Above 1 % predicted, a RuntimeWarning says so, and the report lists it.
        runtime = [str(w.message) for w in caught if w.category is RuntimeWarning]
        assert runtime == report["warnings"]
        if report["predicted_error"] > 0.01:
            assert len(runtime) == 1 and "predicted error" in runtime[0]
    # The error falls with alpha (measured 0.0189 -> 0.0100).
    assert errors[4] < 0.6 * errors[2]
    with pytest.warns(RuntimeWarning, match=rf"method {method}: predicted error"):
        coatfft.make_operator(grid, steel, method=method)


@pytest.mark.parametrize("method", ["frf-spectral", "frf-dcfft"])
def test_g0_options(tin_stack, method):
    grid = coatfft.Grid(64, 48, 0.8e-3, 0.6e-3)
    p = coatfft.hertz_pressure(grid, 2e9, 0.2e-3, "cell_average")
    regularized = quiet_operator(grid, tin_stack, method=method)
    quadrature = quiet_operator(grid, tin_stack, method=method, g0="quadrature", g0_tol=1e-12)
    omitted = quiet_operator(grid, tin_stack, method=method, g0="omitted")
    assert regularized.report["g0_method"] == "regularized"
    assert quadrature.report["g0_method"] == "quadrature"
    assert omitted.report["g0_method"] == "omitted" and omitted.report["g0"] is None
    # Two quadratures of the same integral, each to 1e-10 or better (measured equal to 1e-15).
    assert quadrature.report["g0"] == pytest.approx(regularized.report["g0"], rel=1e-10)
    assert quadrature.report["g0_estimated_error"] <= 1e-12 * quadrature.report["g0"]
    u = regularized(p)
    assert rel_max(quadrature(p), u) <= 1e-10
    # Without g(0) the displacement lacks exactly the mean g(0) F / (alpha^2 lx ly) of the
    # periodic sum: a constant (spread measured 4.8e-16 of max |u|), of that value (1e-14).
    offset = u - omitted(p)
    assert (offset.max() - offset.min()) <= 1e-14 * np.abs(u).max()
    force = p.sum() * grid.dx * grid.dy
    expected = regularized.report["g0"] * force / (4 * grid.lx * grid.ly)
    assert offset.mean() == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("method", ["direct", "dcfft", "frf-spectral", "frf-dcfft", "frf-split"])
def test_threads_and_planning_do_not_change_the_result(steel, tin_stack, method):
    grid = coatfft.Grid(64, 48, 0.8e-3, 0.6e-3)
    body = steel if method in ("direct", "dcfft") else tin_stack
    p = coatfft.hertz_pressure(grid, 2e9, 0.2e-3, "cell_average")
    u = quiet_operator(grid, body, method=method)(p)
    # Another split of the transforms among threads, another FFTW plan: round-off only
    # (measured <= 4.7e-16 of max |u|; 1e-14).
    assert rel_max(quiet_operator(grid, body, method=method, threads=2)(p), u) <= 1e-14
    if method != "direct":  # which uses no FFT, and refuses planning
        measured = quiet_operator(grid, body, method=method, planning="measure")
        assert rel_max(measured(p), u) <= 1e-14


def test_apply_into_out(steel):
    # out=: the result is written into the caller's array (the same values), which is returned;
    # it may be the pressure's own array, since the pressure is read first.
    grid = coatfft.Grid(32, 24, 0.8e-3, 0.6e-3)
    p = coatfft.hertz_pressure(grid, P0, 0.2e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    u = op(p)
    out = np.full(grid.shape, np.nan)
    assert op.apply(p, out=out) is out
    np.testing.assert_array_equal(out, u)
    q = p.copy()
    op(q, out=q)
    np.testing.assert_array_equal(q, u)
    for bad in (np.empty(grid.shape, np.float32), np.empty((grid.nx, grid.ny)).T,
                np.empty((24, 31))):
        with pytest.raises(ValueError, match="apply: out"):
            op(p, out=bad)
    readonly = np.empty(grid.shape)
    readonly.flags.writeable = False
    with pytest.raises(ValueError, match="apply: out: must be a writable, C-contiguous float64"):
        op(p, out=readonly)
    with pytest.raises(TypeError, match="apply: out: expected a numpy array, not list"):
        op(p, out=[0.0])


def test_auto(steel, tin_stack):
    grid = coatfft.Grid(64, 48, 0.8e-3, 0.6e-3)
    p = coatfft.hertz_pressure(grid, 2e9, 0.2e-3, "cell_average")
    # Homogeneous: Love's DC-FFT, exact (docs/auto.md).
    op = coatfft.make_operator(grid, steel)
    assert op.method == "dcfft" and op.report["method_requested"] == "auto"
    assert op.report["auto"]["tolerance"] == 1e-4  # the default
    assert rel_max(op(p), coatfft.make_operator(grid, steel, method="direct")(p)) <= 1e-13
    # Coated, with the keywords of auto: the choice is reported, with what was asked.
    op = coatfft.make_operator(grid, tin_stack, tolerance=1e-3, applications=100,
                               load_radius=0.2e-3, threads=1)
    auto = op.report["auto"]
    assert op.method == auto["method"] == "frf-split"
    assert auto["tolerance"] == 1e-3 and auto["applications"] == 100 and auto["threads"] == 1
    assert auto["reference_loads"] == [{"radius": 0.2e-3, "shape": "hertz"}]
    assert auto["predicted_error"] <= 1e-3
    # The promise of auto: within its tolerance of the exact convolution, here frf-split at its
    # default kernel tolerance (measured 6.8e-9 of max |u|).
    exact = coatfft.make_operator(grid, tin_stack, method="frf-split")(p)
    assert rel_max(op(p), exact) <= 1e-3


def test_operator_properties(steel):
    grid = coatfft.Grid(32, 24, 0.8e-3, 0.6e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    assert op.grid == grid and op.method == "dcfft"
    report = op.report
    assert report["method"] == "dcfft" and report["method_requested"] == "dcfft"
    assert (report["nx"], report["ny"]) == (32, 24)
    assert (report["fft_nx"], report["fft_ny"]) == (64, 48)  # DC-FFT's zero padding
    assert report["warnings"] == [] and "auto" not in report
    assert report["setup_seconds"] >= report["kernel_seconds"] >= 0
    direct = coatfft.make_operator(grid, steel, method="direct")
    assert (direct.report["fft_nx"], direct.report["fft_ny"]) == (0, 0)
    # The report is the operator's: changing the dict handed out changes neither.
    report["method"] = "something else"
    assert op.method == "dcfft" and op.report["method"] == "dcfft"
    # apply and __call__ are the same, and linear: scaling by 2 is exact in floating point.
    p = coatfft.hertz_pressure(grid, P0, 0.2e-3)
    u = op.apply(p)
    np.testing.assert_array_equal(op(p), u)
    np.testing.assert_array_equal(op(2 * p), 2 * u)
    q = coatfft.uniform_disk_pressure(grid, 3e8, 0.1e-3)
    assert rel_max(op(p + q), u + op(q)) <= 1e-14


def test_input_conversions(steel):
    grid = coatfft.Grid(32, 24, 0.8e-3, 0.6e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    rng = np.random.default_rng(3)
    p = rng.uniform(0, 1e9, size=grid.shape)
    u = op(p)
    # A non-contiguous view (transposed, or every other column), Fortran order: same values in,
    # same result out, exactly.
    np.testing.assert_array_equal(op(np.ascontiguousarray(p.T).T), u)
    np.testing.assert_array_equal(op(np.asfortranarray(p)), u)
    wide = np.zeros((24, 64))
    wide[:, ::2] = p
    assert not wide[:, ::2].flags.c_contiguous
    np.testing.assert_array_equal(op(wide[:, ::2]), u)
    # Other dtypes and lists are converted to float64 first.
    p32 = p.astype(np.float32)
    np.testing.assert_array_equal(op(p32), op(p32.astype(np.float64)))
    pint = (p / 1e3).astype(np.int64)
    np.testing.assert_array_equal(op(pint), op(pint.astype(np.float64)))
    np.testing.assert_array_equal(op(p.tolist()), u)
    # The input is not modified.
    before = p.copy()
    op(p)
    np.testing.assert_array_equal(p, before)


def test_output_arrays_own_their_memory(steel):
    grid = coatfft.Grid(32, 24, 0.8e-3, 0.6e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    p = coatfft.hertz_pressure(grid, P0, 0.2e-3)
    u = op(p)
    assert u.dtype == np.float64 and u.shape == (24, 32)
    assert u.flags.c_contiguous and u.flags.writeable
    assert not np.shares_memory(u, p)
    kept = u.copy()
    second = op(p)
    assert not np.shares_memory(u, second)  # each call its own array
    u[0, 0] = -1.0  # writing into it changes nothing else
    np.testing.assert_array_equal(op(p), kept)
    u[0, 0] = kept[0, 0]
    del op, second
    gc.collect()
    # Nothing of the operator is referenced: the array outlives it with its values.
    np.testing.assert_array_equal(u, kept)
    garbage = [np.full((24, 32), 7.0) for _ in range(50)]  # reuse freed memory, if any was freed
    np.testing.assert_array_equal(u, kept)
    del garbage


def test_timing_helpers(steel):
    # coatfft._coatfft.timing, the C++ side of bench/bench_python.py: medians of C++ loops.
    timing = coatfft._coatfft.timing
    grid = coatfft.Grid(32, 24, 0.8e-3, 0.6e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    p = coatfft.hertz_pressure(grid, P0, 0.2e-3)
    seconds = timing.apply_seconds(op, p, 3)
    assert 0 < seconds < 1
    k = np.logspace(0, 8, 1000)
    assert 0 < timing.frf_loop_seconds(steel, k, 3) < 1
    with pytest.raises(ValueError, match="repeat = 0 must be >= 1"):
        timing.apply_seconds(op, p, 0)
    with pytest.raises(ValueError, match=r"pressure: shape \(24, 31\), but the grid needs"):
        timing.apply_seconds(op, p[:, 1:], 1)
    with pytest.raises(TypeError, match="body: expected a LayerStack"):
        timing.frf_loop_seconds("steel", k, 1)


def test_reprs(steel):
    # What an interactive session shows: the class, and what tells one object from another.
    grid = coatfft.Grid(32, 24, 0.8e-3, 0.6e-3)
    op = coatfft.make_operator(grid, steel, method="dcfft")
    assert repr(op) == "Operator(method='dcfft', grid=Grid(nx=32, ny=24, lx=0.0008, ly=0.0006))"
    user = coatfft.UserFrf(lambda k: 2 / (steel.E_star * k), 2e-11, 3e-11)
    assert repr(user) == "UserFrf(name='user', c0=2e-11, c_inf=3e-11)"
    x, y = np.meshgrid(grid.x, grid.y)
    result = coatfft.solve_contact(op, (x**2 + y**2) / 0.02, load=1.0)
    assert repr(result).startswith("ContactResult(status='converged', iterations=")


def test_periodic_boundary_against_the_wavy_closed_form(steel, tin_stack):
    # One period of p = p0 cos(k x) on 64 cells, uniform in y: u = 2 p0 cos(k x) / (E* k)
    # (Johnson 1985, section 13.2). The cell-wise constant load changes the amplitude by
    # sinc(k dx / 2) and its aliases by about (k dx)^2 / (4 pi^2): 4e-4 and 2.4e-4 here.
    lam, p0 = 1e-3, 1e8
    grid = coatfft.Grid(64, 2, lam, 2 * lam / 64)
    p = p0 * np.cos(2 * np.pi * grid.x / lam)[np.newaxis, :].repeat(2, axis=0)
    exact = 2 * p / (steel.E_star * 2 * np.pi / lam)
    for method in ("auto", "dcfft", "frf-split"):
        op = coatfft.make_operator(grid, steel, method=method, boundary="periodic")
        assert op.report["boundary"] == "periodic"
        assert op.report["fft_nx"] == 64
        assert rel_max(op.apply(p), exact) < 1e-3, method
    # A coated body's periodic operator: auto takes frf-split, and 2 um of TiN (stiffer than
    # steel) make the surface stiffer, by about k h (E*_steel / E*_TiN - 1) ~ 1e-2 (docs/theory.md).
    coated = coatfft.make_operator(grid, tin_stack, boundary="periodic")
    assert coated.method == "frf-split"
    bare = np.abs(coatfft.make_operator(grid, steel, boundary="periodic").apply(p)).max()
    assert 0.9 * bare < np.abs(coated.apply(p)).max() < bare
    # A film far thinner than a cell (1 pm against 16 um): auto leaves it out where its effect
    # is within the tolerance, as a scene's periodic auto does (model/operator_plan.hpp), and
    # builds Love's operator of the bare substrate, its displacement the bare one's.
    film = coatfft.LayerStack(steel, [coatfft.Coating(tin_stack.coatings[0].material, 1e-12)])
    reduced = coatfft.make_operator(grid, film, boundary="periodic")
    assert reduced.method == "dcfft"
    assert rel_max(reduced.apply(p), exact) < 1e-3


def test_periodic_boundary_refusals(steel):
    grid = coatfft.Grid(16, 16, 1e-3, 1e-3)
    with pytest.raises(ValueError, match='"frf-spectral" computes free'):
        coatfft.make_operator(grid, steel, method="frf-spectral", boundary="periodic")
    with pytest.raises(ValueError, match='boundary = "closed" is not one of "free", "periodic"'):
        coatfft.make_operator(grid, steel, boundary="closed")
    with pytest.raises(ValueError, match="tolerance: applies only to free boundaries"):
        coatfft.make_operator(grid, steel, boundary="periodic", tolerance=1e-3)
    for keyword in ("load_radius", "applications"):
        with pytest.raises(ValueError, match=f"{keyword}: applies only to free boundaries"):
            coatfft.make_operator(grid, steel, boundary="periodic", **{keyword: 1e-4})
    # A named method on a periodic boundary takes the keys it takes on a free one.
    with pytest.raises(ValueError, match='alpha: applies only to the FRF pipelines'):
        coatfft.make_operator(grid, steel, method="dcfft", boundary="periodic", alpha=2.0)
