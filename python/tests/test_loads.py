"""The grid, the known pressures and the displacement references: Grid, hertz_pressure,
uniform_disk_pressure, hertz_displacement, uniform_disk_displacement, hankel_displacement (their
errors: test_errors.py)."""
import numpy as np
import pytest

import coatfft
from conftest import radius

ROUND_OFF = 4e-16  # a few roundings of the same formula computed two ways


def check_field(array, grid):
    """Every field the module returns: float64, C order, (ny, nx), writable, its own memory."""
    assert isinstance(array, np.ndarray) and array.dtype == np.float64
    assert array.shape == grid.shape and array.flags.c_contiguous and array.flags.writeable


def test_grid_properties():
    # nx != ny and lx/nx != ly/ny, so that a swapped axis shows.
    g = coatfft.Grid(5, 3, 2.0, 0.3)
    assert (g.nx, g.ny, g.lx, g.ly) == (5, 3, 2.0, 0.3)
    assert g.shape == (3, 5)
    assert g.dx == pytest.approx(0.4, rel=ROUND_OFF) and g.dy == pytest.approx(0.1, rel=ROUND_OFF)
    # Cell centres over [-lx/2, lx/2]: x_i = -lx/2 + (i + 1/2) dx; an odd count has one at 0.
    # (atol: the centre's exact 0 may come out as a rounding of -lx/2 + lx/2.)
    np.testing.assert_allclose(g.x, [-0.8, -0.4, 0.0, 0.4, 0.8], rtol=ROUND_OFF, atol=1e-16)
    np.testing.assert_allclose(g.y, [-0.1, 0.0, 0.1], rtol=ROUND_OFF, atol=1e-17)
    assert g.x.shape == (5,) and g.y.shape == (3,) and g.x.dtype == np.float64
    even = coatfft.Grid(4, 2, 1.0, 1.0)
    np.testing.assert_allclose(even.x, [-0.375, -0.125, 0.125, 0.375], rtol=0, atol=1e-17)
    assert repr(g) == "Grid(nx=5, ny=3, lx=2.0, ly=0.3)"
    assert g == coatfft.Grid(5, 3, 2.0, 0.3) and g != coatfft.Grid(3, 5, 2.0, 0.3)
    assert g != coatfft.Grid(5, 3, 2.0, 0.31)
    assert g != 3 and not (g == "grid")  # another type is unequal, not a TypeError


# Non-square cells and a non-square grid: an (nx, ny) mix-up or a transposed field shows.
GRID = coatfft.Grid(40, 24, 4e-3, 2e-3)


def test_hertz_pressure_centre_sampling():
    p0, a = 1e9, 0.9e-3
    p = coatfft.hertz_pressure(GRID, p0, a)
    check_field(p, GRID)
    r = radius(GRID)
    # sqrt((a - r)(a + r)) / a: no cancellation near the edge. What is left is the rounding of
    # r itself, amplified there by d ln sqrt(a^2 - r^2) / d ln r = r^2 / (a^2 - r^2), at most 25
    # on this grid: 1e-14 of p0 bounds it (measured 3.7e-14 relative with 1 - r^2/a^2).
    expected = p0 * np.sqrt(np.clip((a - r) * (a + r), 0, None)) / a
    np.testing.assert_allclose(p, expected, rtol=0, atol=1e-14 * p0)
    assert np.count_nonzero(p) == np.count_nonzero(r < a)
    # "centre" is the default.
    np.testing.assert_array_equal(coatfft.hertz_pressure(GRID, p0, a, sampling="centre"), p)


def gauss_cell_average(grid, function, i, j, n=24):
    """The mean of function(r) over cell (j, i) by n x n Gauss-Legendre points: for a cell the
    load's edge does not cross, the integrand is analytic there, and 24 points reach round-off
    even for a cell next to the edge's branch point (measured: 12 points 3e-10 of p0, 24 points
    1.8e-15, 96 points 4.8e-15)."""
    t, w = np.polynomial.legendre.leggauss(n)
    x = grid.x[i] + 0.5 * grid.dx * t
    y = grid.y[j] + 0.5 * grid.dy * t
    xx, yy = np.meshgrid(x, y)
    return 0.25 * np.einsum("i,j,ij->", w, w, function(np.hypot(xx, yy)))


def cells_inside_outside(grid, a):
    """Masks (ny, nx) of the cells wholly inside r < a (the farthest corner inside: the disk is
    convex) and wholly outside (the nearest point of the cell outside); the rest are crossed."""
    x, y = np.meshgrid(np.abs(grid.x), np.abs(grid.y))
    far = np.hypot(x + grid.dx / 2, y + grid.dy / 2)
    near = np.hypot(np.maximum(x - grid.dx / 2, 0), np.maximum(y - grid.dy / 2, 0))
    return far < a, near >= a


def test_hertz_pressure_cell_average():
    p0, a = 1e9, 0.9e-3
    p = coatfft.hertz_pressure(GRID, p0, a, "cell_average")
    check_field(p, GRID)
    # Cell averages are exact cell forces: their sum is the load (2/3) pi p0 a^2 to round-off
    # (measured 2.2e-16; 1e-14 allows the sum of 960 cells).
    total = p.sum() * GRID.dx * GRID.dy
    assert total == pytest.approx(2 / 3 * np.pi * p0 * a * a, rel=1e-14)
    inside, outside = cells_inside_outside(GRID, a)
    assert np.all(p[outside] == 0) and np.all(p[~outside] > 0) and np.all(p <= p0)
    hertz = lambda r: p0 * np.sqrt((a - r) * (a + r)) / a  # noqa: E731
    for j, i in zip(*np.nonzero(inside)):
        assert abs(p[j, i] - gauss_cell_average(GRID, hertz, i, j)) <= 1e-14 * p0


def test_uniform_disk_pressure():
    p_disk, a = 5e7, 0.77e-3
    centre = coatfft.uniform_disk_pressure(GRID, p_disk, a)
    check_field(centre, GRID)
    r = radius(GRID)
    np.testing.assert_array_equal(centre, np.where(r < a, p_disk, 0.0))
    average = coatfft.uniform_disk_pressure(GRID, p_disk, a, sampling="cell_average")
    check_field(average, GRID)
    # The exact cell forces sum to pi p a^2 (round-off, as above).
    assert average.sum() * GRID.dx * GRID.dy == pytest.approx(np.pi * p_disk * a * a, rel=1e-14)
    inside, outside = cells_inside_outside(GRID, a)
    np.testing.assert_allclose(average[inside], p_disk, rtol=1e-14)
    assert np.all(average[outside] == 0)
    crossed = ~inside & ~outside
    assert np.all((average[crossed] > 0) & (average[crossed] < p_disk))


def johnson_hertz(r, p0, a, e_star):
    """Johnson (1985) eq. 3.41: u_z under p0 sqrt(1 - r^2/a^2), written out independently."""
    r = np.asarray(r, dtype=float)
    inside = np.pi * p0 * (2 * a * a - r * r) / (4 * a * e_star)
    ro = np.maximum(r, a)
    outside = p0 / (2 * a * e_star) * (
        (2 * a * a - ro * ro) * np.arcsin(a / ro) + ro * a * np.sqrt(1 - (a / ro) ** 2))
    return np.where(r <= a, inside, outside)


def elliptic_k_e(m):
    """Complete elliptic integrals K(m), E(m) (parameter m = k^2 < 1) by the arithmetic-geometric
    mean (Abramowitz & Stegun 17.6), to round-off."""
    a, b, c = np.ones_like(m), np.sqrt(1 - m), np.sqrt(m)
    total, power = 0.5 * c * c, 0.5
    for _ in range(12):  # quadratic convergence: 12 steps reach round-off for m <= 0.99999
        a, b, c = 0.5 * (a + b), np.sqrt(a * b), 0.5 * (a - b)
        power *= 2
        total = total + power * c * c
    k = np.pi / (2 * a)
    return k, k * (1 - total)


def johnson_uniform_disk(r, p, a, e_star):
    """Johnson (1985) eq. 3.36 with the elliptic integrals above: r < a 4pa/(pi E*) E(r/a),
    r > a 4pr/(pi E*) [E(a/r) - (1 - a^2/r^2) K(a/r)]."""
    r = np.asarray(r, dtype=float)
    inside = np.minimum(r / a, 1.0)
    _, e_in = elliptic_k_e(inside ** 2)
    outside = a / np.maximum(r, a)
    k_out, e_out = elliptic_k_e(outside ** 2)
    u_in = 4 * p * a / (np.pi * e_star) * e_in
    u_out = 4 * p * r / (np.pi * e_star) * (e_out - (1 - outside ** 2) * k_out)
    return np.where(r < a, u_in, u_out)


RADII = np.array([0.0, 0.1, 0.5, 0.9, 0.999, 1.001, 1.5, 3.0, 20.0]) * 1e-3  # a = 1 mm


def test_hertz_displacement_closed_form(steel):
    p0, a = 1e9, 1e-3
    u = coatfft.hertz_displacement(RADII, p0, a, steel.E_star)
    assert u.shape == RADII.shape and u.dtype == np.float64
    # Both are the same closed form, evaluated in different orders: 1e-14 of u(0).
    u0 = np.pi * p0 * a / (2 * steel.E_star)
    np.testing.assert_allclose(u, johnson_hertz(RADII, p0, a, steel.E_star), rtol=0,
                               atol=1e-14 * u0)
    assert u[0] == pytest.approx(u0, rel=ROUND_OFF)
    # Any shape: a scalar, a list, a 2-D array (r of a grid).
    assert coatfft.hertz_displacement(0.0, p0, a, steel.E_star).shape == ()
    np.testing.assert_array_equal(coatfft.hertz_displacement(list(RADII), p0, a, steel.E_star), u)
    r2 = RADII.reshape(3, 3)
    np.testing.assert_array_equal(coatfft.hertz_displacement(r2, p0, a, steel.E_star),
                                  u.reshape(3, 3))
    np.testing.assert_array_equal(coatfft.hertz_displacement(r2.T, p0, a, steel.E_star),
                                  u.reshape(3, 3).T)


def test_uniform_disk_displacement_closed_form(steel):
    p, a = 1e6, 1e-3
    u = coatfft.uniform_disk_displacement(RADII, p, a, steel.E_star)
    # u(0) = 2 p a / E* and u(a) = 4 p a / (pi E*) (Johnson eq. 3.36): exact values.
    assert u[0] == pytest.approx(2 * p * a / steel.E_star, rel=ROUND_OFF)
    edge = coatfft.uniform_disk_displacement(np.array([a]), p, a, steel.E_star)[0]
    assert edge == pytest.approx(4 * p * a / (np.pi * steel.E_star), rel=1e-14)
    # Elsewhere against the AGM elliptic integrals (each to ~1e-15): 1e-13 of u(0) leaves room for
    # the log singularity of K near r = a (r = 0.999 a and 1.001 a are in RADII).
    np.testing.assert_allclose(u, johnson_uniform_disk(RADII, p, a, steel.E_star), rtol=0,
                               atol=1e-13 * u[0])
    # Far away it is a point force P = pi p a^2: u -> P / (pi E* r) (Boussinesq), above it by
    # k^2/8 + 3 k^4/64 + ... relative, k = a/r (the expansion of E - (1 - k^2) K).
    k = a / RADII[-1]
    excess = u[-1] / (p * a * a / (steel.E_star * RADII[-1])) - 1
    assert k * k / 8 < excess < k * k / 8 + k ** 4 / 16


def test_hankel_displacement_of_half_space(steel):
    p0, a = 1e9, 1e-3
    # The Hankel integral of H = 2/(E* k) is the Hertz and disk closed forms (docs: Hankel
    # integrals at rel_tol 1e-10 may differ by 2e-10 of u(0); 1e-9 allows that five times).
    for body in (steel, coatfft.LayerStack(steel)):
        u = coatfft.hankel_displacement(body, RADII, p0, a)
        assert u.shape == RADII.shape
        ref = coatfft.hertz_displacement(RADII, p0, a, steel.E_star)
        np.testing.assert_allclose(u, ref, rtol=0, atol=1e-9 * ref[0])
        u = coatfft.hankel_displacement(body, RADII, 1e6, a, load="uniform_disk")
        ref = johnson_uniform_disk(RADII, 1e6, a, steel.E_star)
        np.testing.assert_allclose(u, ref, rtol=0, atol=1e-9 * ref[0])
    # Any shape of r.
    u2 = coatfft.hankel_displacement(steel, RADII.reshape(3, 3), p0, a, "hertz", 1e-8)
    assert u2.shape == (3, 3)
    np.testing.assert_allclose(u2.ravel(), coatfft.hertz_displacement(RADII, p0, a, steel.E_star),
                               rtol=1e-8)


def test_hankel_displacement_far_away(steel, tin_stack):
    """Far beyond the quadrature's reach the substrate's half-space: u = F c0 / (2 pi r) with
    F = 2 pi p0 a^2 / 3 (it was NaN at r = 1e300 m), finite and exact for a coated body too."""
    p0, a = 1e9, 1e-3
    r = np.array([1e10, 1e100, 1e300])
    c0 = 2 / steel.E_star
    for body in (steel, tin_stack):
        u = coatfft.hankel_displacement(body, r, p0, a)
        assert np.all(np.isfinite(u))
        np.testing.assert_allclose(u, p0 * a * a * c0 / 3 / r, rtol=1e-12)


def test_hankel_displacement_quadrature(steel, tin):
    """A UserFrf with a part of k H that is not constant, so that the integral is a quadrature:
    H = c_inf/k + (c0 - c_inf) exp(-k h)/k, whose second term is Boussinesq's kernel
    1/sqrt(r^2 + h^2) (the Laplace transform of J0), integrated here independently."""
    c0, c_inf = 2 / steel.E_star, 2 / tin.E_star
    a = 1e-3
    h = 0.3 * a

    def frf(k):
        return c_inf / k + (c0 - c_inf) * np.exp(-k * h) / k

    user = coatfft.UserFrf(frf, c0, c_inf)
    p = 1e6
    # Uniform disk at r = 0: integral of p / sqrt(rho^2 + h^2) over the disk, in closed form.
    exact = p * (c_inf * a + (c0 - c_inf) * (np.sqrt(a * a + h * h) - h))
    u = coatfft.hankel_displacement(user, np.array([0.0]), p, a, load="uniform_disk")
    assert u[0] == pytest.approx(exact, rel=1e-9)  # the quadrature's rel_tol 1e-10, x 10
    # Hertz at r = 0: the half-space part in closed form (pi p0 a / 4 per unit c), the rest by
    # 200-point Gauss-Legendre in rho = a sin(theta) (analytic integrand: exact to 1e-15).
    p0 = 1e9
    t, w = np.polynomial.legendre.leggauss(200)
    theta, w = (t + 1) * np.pi / 4, w * np.pi / 4
    rho = a * np.sin(theta)
    kernel = p0 * np.cos(theta) * rho * a * np.cos(theta) / np.sqrt(rho ** 2 + h * h)
    exact = c_inf * np.pi * p0 * a / 4 + (c0 - c_inf) * np.sum(w * kernel)
    calls = user.calls
    u = coatfft.hankel_displacement(user, np.array([0.0]), p0, a)
    assert u[0] == pytest.approx(exact, rel=1e-9)
    assert user.calls > calls  # the function was called: the integral is not the closed form


def test_hankel_displacement_of_coated_body(steel, tin, tin_stack):
    p0, a = 2e9, 0.2e-3
    r = np.array([0.0, 0.5 * a, 2 * a])
    u = coatfft.hankel_displacement(tin_stack, r, p0, a)
    # A 2 um stiffer coating under a = 0.2 mm: between bare TiN and bare steel, near steel
    # (tin_2um.toml: 0.33 % below steel at the centre).
    steel_u = coatfft.hertz_displacement(r, p0, a, steel.E_star)
    tin_u = coatfft.hertz_displacement(r, p0, a, tin.E_star)
    assert np.all(u < steel_u) and np.all(u > tin_u)
    assert u[0] / steel_u[0] == pytest.approx(1 - 0.0033, abs=0.0005)
