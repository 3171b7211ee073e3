// Cerruti's influence coefficients of a uniformly sheared rectangle (docs/theory.md 1.3b) against
// independent references: a Cartesian adaptive 2-D quadrature of the point-force solution over
// the cell, the point force far away, the exact symmetries, a polar quadrature of Boussinesq's
// radial displacement under a uniform pressure (reciprocity and sign), and uniformly loaded
// patches of cells (a rectangle, and a disk with its closed form).
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "convolution/kernels/cerruti_influence.hpp"
#include "core/detail/gsl_quadrature.hpp"
#include "core/error.hpp"
#include "long_double_gauss_legendre.hpp"
#include "materials/material.hpp"

using coatfft::cerruti_influence;
using coatfft::CerrutiCoefficients;
using coatfft::Material;

namespace {

using std::numbers::pi;

// A material with mu = 1 Pa: the coefficients are then the length integrals of docs/theory.md
// (1.5b)-(1.5d).
Material unit_shear(double nu) {
  return Material(2.0 * (1.0 + nu), nu);
}

// Cerruti's point force Q_x = 1 N at the origin, surface displacements at (X, Y) for mu = 1 Pa
// (Johnson 1985, §3.3, at z = 0, with (1 + nu)/E = 1/(2 mu)), docs/theory.md (1.5a):
// u_x = [(1 - nu)/R + nu X^2/R^3]/(2 pi), u_y = nu X Y/(2 pi R^3), u_z = (1 - 2nu) X/(4 pi R^2).
double kernel_xx(double X, double Y, double nu) {
  const double r = std::hypot(X, Y);
  return ((1.0 - nu) / r + nu * X * X / (r * r * r)) / (2.0 * pi);
}
double kernel_yx(double X, double Y, double nu) {
  const double r = std::hypot(X, Y);
  return nu * X * Y / (2.0 * pi * r * r * r);
}
double kernel_zx(double X, double Y, double nu) {
  return (1.0 - 2.0 * nu) * X / (4.0 * pi * (X * X + Y * Y));
}

// The pieces of [lo, hi] split at s where s lies inside: the kernels are singular at the field
// point, which then becomes an end point of the adaptive rule (QAGS extrapolates end-point
// singularities; its nodes are interior, so the singular point itself is never sampled).
std::vector<std::array<double, 2>> pieces(double lo, double hi, double s) {
  if (s > lo && s < hi) return {{lo, s}, {s, hi}};
  return {{lo, hi}};
}

// Independent reference: \int_{ylo}^{yhi} \int_{xlo}^{xhi} f(x', y') dx' dy' by nested adaptive
// Gauss-Kronrod quadrature (GSL QAGS), inner over x' split at xs, outer over y' split at ys.
// Tolerances 2e-14 (inner) and 1e-13 (outer), relative, or 1e-18 absolute for values near 0.
// Every inner and outer error estimate must be within 1e-12 of its value.
double nested_quadrature(const std::function<double(double, double)>& f, double xlo, double xhi,
                         double xs, double ylo, double yhi, double ys) {
  const coatfft::detail::GslHandlerOff quiet;
  auto inner_ws = coatfft::detail::make_gsl_workspace(1000);
  auto outer_ws = coatfft::detail::make_gsl_workspace(1000);
  double worst = 0.0;  // the largest inner error estimate relative to its value (or 1e-18)
  const auto inner = [&](double yp) {
    double sum = 0.0;
    for (const auto& p : pieces(xlo, xhi, xs)) {
      const auto r = coatfft::detail::gsl_qags([&](double xp) { return f(xp, yp); }, p[0], p[1],
                                               1e-18, 2e-14, inner_ws.get());
      worst = std::max(worst, r.error / std::max(std::abs(r.value), 1e-6));
      sum += r.value;
    }
    return sum;
  };
  double total = 0.0;
  for (const auto& p : pieces(ylo, yhi, ys)) {
    const auto r = coatfft::detail::gsl_qags(inner, p[0], p[1], 1e-18, 1e-13, outer_ws.get());
    // QAGS may stop on rounding (the inner values carry ~1e-15 noise); its estimate still holds.
    REQUIRE((r.status == GSL_SUCCESS || r.status == GSL_EROUND));
    REQUIRE(r.error <= 1e-12 * std::abs(r.value) + 1e-17);
    total += r.value;
  }
  REQUIRE(worst <= 1e-12);
  return total;
}

// The cell integral of kernel(x - x', y - y') over |x'| <= a, |y'| <= b.
double cell_quadrature(double (*kernel)(double, double, double), double nu, double x, double y,
                       double dx, double dy) {
  return nested_quadrature([&](double xp, double yp) { return kernel(x - xp, y - yp, nu); },
                           -0.5 * dx, 0.5 * dx, x, -0.5 * dy, 0.5 * dy, y);
}

// The same for the (z, x) kernel X/R^2 (odd in X), folded onto x' >= 0 so that its value keeps
// its relative accuracy near x = 0 (no cancellation between x' and -x'): pointwise,
//   (x - x')/R1^2 + (x + x')/R2^2 = 2 x (x^2 - x'^2 + Y^2)/(R1^2 R2^2).
double cell_quadrature_zx(double nu, double x, double y, double dx, double dy) {
  const auto folded = [&](double xp, double yp) {
    const double Y = y - yp;
    const double r1 = (x - xp) * (x - xp) + Y * Y;
    const double r2 = (x + xp) * (x + xp) + Y * Y;
    return (1.0 - 2.0 * nu) / (4.0 * pi) * 2.0 * x * (x * x - xp * xp + Y * Y) / (r1 * r2);
  };
  return nested_quadrature(folded, 0.0, 0.5 * dx, std::abs(x), -0.5 * dy, 0.5 * dy, y);
}

// Length of the part of the ray from (x, y) along theta inside |x'| <= a, |y'| <= b (slab method).
double ray_chord(double theta, double x, double y, double a, double b) {
  const std::array<double, 2> origin = {x, y};
  const std::array<double, 2> dir = {std::cos(theta), std::sin(theta)};
  const std::array<double, 2> half = {a, b};
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 2; ++k) {
    if (std::abs(dir[k]) < 1e-300) {
      if (std::abs(origin[k]) > half[k]) return 0.0;
      continue;
    }
    double ta = (-half[k] - origin[k]) / dir[k];
    double tb = (half[k] - origin[k]) / dir[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return std::max(0.0, t1 - t0);
}

// Independent reference for reciprocity: u_x at (x, y) under a unit uniform pressure on the cell,
// from Boussinesq's radial displacement u_r = -(1 - 2nu)(1 + nu) P/(2 pi E R) (towards the load,
// Johnson 1985, §3.2, at z = 0; for mu = 1 Pa the prefactor is (1 - 2nu)/(4 pi)). About the
// field point, x' = x + R cos(theta): u_x = -(1 - 2nu)/(4 pi) \iint (x - x')/R^2 dA
// = (1 - 2nu)/(4 pi) \int cos(theta) chord(theta) dtheta, by GSL QAG split at the corner
// directions, where the chord has kinks.
double pressure_ux_polar(double x, double y, double dx, double dy, double nu) {
  const double a = 0.5 * dx;
  const double b = 0.5 * dy;
  std::vector<double> cuts = {-pi, pi};
  for (double cx : {-a, a})
    for (double cy : {-b, b})
      if (cx != x || cy != y) cuts.push_back(std::atan2(cy - y, cx - x));
  std::sort(cuts.begin(), cuts.end());
  const coatfft::detail::GslHandlerOff quiet;
  auto ws = coatfft::detail::make_gsl_workspace(1000);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] <= cuts[i]) continue;
    const auto r = coatfft::detail::gsl_qag(
        [&](double t) { return std::cos(t) * ray_chord(t, x, y, a, b); }, cuts[i], cuts[i + 1],
        1e-17 * std::max(dx, dy), 2e-14, GSL_INTEG_GAUSS21, ws.get());
    // At x = 0 the integral is 0 and the tolerance unattainable: GSL_EROUND with a tiny estimate.
    REQUIRE((r.status == GSL_SUCCESS || r.status == GSL_EROUND));
    INFO("QAG piece " << i << ": " << r.value << " +- " << r.error);
    REQUIRE(r.error <= 1e-13 * std::abs(r.value) + 1e-14 * std::max(dx, dy));
    sum += r.value;
  }
  return (1.0 - 2.0 * nu) / (4.0 * pi) * sum;
}

struct Point {
  double x, y, dx, dy;
};

// Inside, on the edges, at the corners, at the centre, outside, near and beyond the 8 max(dx, dy)
// switch to Gauss-Legendre, far outside; square and 1:10 cells (both orientations).
const std::vector<Point>& field_points() {
  static const std::vector<Point> points = {
      {0.0, 0.0, 1.0, 1.0},    {0.2, 0.1, 1.0, 1.0},   {0.5, 0.1, 1.0, 1.0},
      {0.5, 0.5, 1.0, 1.0},    {-0.5, 0.3, 1.0, 1.0},  {0.1, -0.5, 1.0, 1.0},
      {1.3, -0.7, 1.0, 1.0},   {3.0, 2.0, 1.0, 1.0},   {7.9, 0.4, 1.0, 1.0},
      {8.1, -0.4, 1.0, 1.0},   {30.0, 17.0, 1.0, 1.0}, {-300.0, 450.0, 1.0, 1.0},
      {0.0, 0.03, 1.0, 0.1},   {0.3, 0.02, 1.0, 0.1},  {0.5, 0.05, 1.0, 0.1},
      {-0.5, 0.0, 1.0, 0.1},   {0.2, 0.05, 1.0, 0.1},  {0.51, -0.049, 1.0, 0.1},
      {0.7, 0.3, 1.0, 0.1},    {-2.0, 1.5, 1.0, 0.1},  {5.0, -7.0, 1.0, 0.1},
      {60.0, 25.0, 1.0, 0.1},  {0.02, 0.3, 0.1, 1.0},  {0.05, -0.5, 0.1, 1.0},
      {0.049, 0.51, 0.1, 1.0}, {-1.1, 2.0, 0.1, 1.0},  {6.0, 5.5, 0.1, 1.0},
      {-20.0, 90.0, 0.1, 1.0}, {1e-3, 0.3, 1.0, 1.0},  {2e-3, 40.0, 1.0, 1.0}};
  return points;
}

}  // namespace

TEST_CASE("cerruti_influence equals a 2-D adaptive quadrature of Cerruti's point-force solution",
          "[convolution][cerruti]") {
  // Measured differences at these points and nu = 0, 0.3, 0.45: <= 1.0e-14 (xx, the corner sum's
  // cancellation for a 1:10 cell, ~64 eps max/min(dx, dy) at most, as Love's), 6.2e-15 (yx),
  // 3.1e-15 (zx). The nested QAGS is asked for 1e-13; 1e-12 leaves margin and still catches any
  // slip in a formula (a wrong corner term changes the result at O(1)); the far-field rules are
  // checked to rounding by the switch test below.
  for (const double nu : {0.3, 0.0, 0.45}) {
    const Material m = unit_shear(nu);
    for (const Point& p : field_points()) {
      INFO("nu = " << nu << ", x = " << p.x << ", y = " << p.y << ", dx = " << p.dx
                   << ", dy = " << p.dy);
      const CerrutiCoefficients c = cerruti_influence(p.x, p.y, p.dx, p.dy, m);
      const double rxx = cell_quadrature(kernel_xx, nu, p.x, p.y, p.dx, p.dy);
      const double ryx = cell_quadrature(kernel_yx, nu, p.x, p.y, p.dx, p.dy);
      const double rzx = cell_quadrature_zx(nu, p.x, p.y, p.dx, p.dy);
      CHECK(c.xx == Approx(rxx).epsilon(1e-12).margin(0.0));
      // Where yx vanishes by symmetry (x = 0 or y = 0) the quadrature returns rounding noise:
      // an absolute bound there, on the scale of xx.
      CHECK(c.yx == Approx(ryx).epsilon(1e-12).margin(1e-15 * c.xx));
      CHECK(c.zx == Approx(rzx).epsilon(1e-12).margin(0.0));
    }
  }
  // Near the axis x = 0, zx = c1 x + c3 x^3: zx/x at x = 1e-9 and 1e-6 agree to ~c3/c1 1e-12
  // unless the closed form cancels (which would cost ~eps/x = 1e-7 relative at 1e-9).
  const Material m = unit_shear(0.3);
  for (const Point& p : {Point{0, 0.3, 1.0, 1.0}, Point{0, 0.5, 1.0, 1.0}, Point{0, 2.0, 1.0, 0.1},
                         Point{0, 0.0, 0.1, 1.0}, Point{0, 40.0, 1.0, 1.0}}) {
    INFO("y = " << p.y << ", dx = " << p.dx << ", dy = " << p.dy);
    const double slope = cerruti_influence(1e-9, p.y, p.dx, p.dy, m).zx / 1e-9;
    CHECK(cerruti_influence(1e-6, p.y, p.dx, p.dy, m).zx / 1e-6 ==
          Approx(slope).epsilon(1e-10).margin(0.0));
  }
}

// Reference for the far field: a 30 x 30 Gauss-Legendre rule of the kernels (mu = 1 Pa) in long
// double, nodes by Newton's iteration on P_n (independent of the library's tables). Beyond 8
// cells it converges like (4 r/d)^(-60): exact to long-double rounding. The zx kernel is summed
// in node pairs +-t as 2 x (x^2 - a^2 t^2 + Y^2)/(R1^2 R2^2) (pointwise equal to the two terms)
// so that it keeps its relative accuracy near x = 0.
std::array<long double, 2> cerruti_long_double_rule(long double x, long double y, long double a,
                                                    long double b, long double nu) {
  const LongDoubleRule rule = long_double_gauss_legendre(30);
  const std::vector<long double>& t = rule.nodes;
  const std::vector<long double>& w = rule.weights;
  long double sxx = 0.0L;
  long double szx = 0.0L;
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (std::size_t j = 0; j < t.size(); ++j) {
      const long double ex = x - a * t[i];
      const long double ey = y - b * t[j];
      const long double r2 = ex * ex + ey * ey;
      sxx += w[i] * w[j] * (1.0L - nu * ey * ey / r2) / std::sqrt(r2);
      if (t[i] > 0) {  // n is even: the pairs +-t cover every node
        const long double at = a * t[i];
        const long double r1 = (x - at) * (x - at) + ey * ey;
        const long double r3 = (x + at) * (x + at) + ey * ey;
        szx += w[i] * w[j] * 2.0L * x * (x * x - at * at + ey * ey) / (r1 * r3);
      }
    }
  }
  const long double pi_l = std::numbers::pi_v<long double>;
  return {a * b * sxx / (2.0L * pi_l), a * b * (1.0L - 2.0L * nu) / (4.0L * pi_l) * szx};
}

TEST_CASE("cerruti_influence is exact on both sides of each far-field rule switch",
          "[convolution][cerruti]") {
  // The rules change at r = 8, 12, 48, 256, 4096 max(dx, dy) (n = 6, 5, 4, 3, 2 beyond). Just
  // inside and just outside each switch, along the axes and off them, square and 1:10 cells.
  // Measured: the rules within 6.3e-16 of the exact xx and zx (rounding); 2e-15 still catches a
  // rule one order too low (checked: with n - 1 at every switch this case fails at 8, 12, 48 and
  // 256; 2 points is the lowest rule). Just inside 8 the closed forms cancel: ~64 eps
  // max/min(dx, dy) for xx (1.6e-13 at 1:10), hence 5e-13 there.
  const double nu = 0.3;
  const Material m = unit_shear(nu);
  for (const Point cell : {Point{0, 0, 1.0, 1.0}, Point{0, 0, 1.0, 0.1}, Point{0, 0, 0.1, 1.0}}) {
    const double d = std::max(cell.dx, cell.dy);
    for (const double ratio : {8.0, 12.0, 48.0, 256.0, 4096.0}) {
      for (const double side : {0.999, 1.001}) {
        for (const double angle : {0.0, 0.6, 1.2, 0.5 * pi - 0.01}) {
          const double r = side * ratio * d;
          const double x = r * std::cos(angle);
          const double y = r * std::sin(angle);
          INFO("dx = " << cell.dx << ", dy = " << cell.dy << ", r/d = " << r / d
                       << ", angle = " << angle);
          const auto reference = cerruti_long_double_rule(x, y, 0.5L * cell.dx, 0.5L * cell.dy, nu);
          const CerrutiCoefficients c = cerruti_influence(x, y, cell.dx, cell.dy, m);
          const double tol = side < 1.0 && ratio == 8.0 ? 5e-13 : 2e-15;
          CHECK(c.xx == Approx(static_cast<double>(reference[0])).epsilon(tol).margin(0.0));
          CHECK(c.zx == Approx(static_cast<double>(reference[1])).epsilon(tol).margin(0.0));
        }
      }
    }
  }
}

TEST_CASE("cerruti_influence tends to the point force of Q = dx dy far away",
          "[convolution][cerruti]") {
  // The cell mean of a kernel K is K + (a^2 K_xx + b^2 K_yy)/6 + O(d^4/r^5): relative error
  // O((d/r)^2). Measured max |u/point - 1| (r/d)^2 over these directions and cells: 0.084 (xx),
  // 0.28 (yx), 0.19 (zx); bound 0.5. The error must also fall at least 4-fold per doubling of r
  // (second order, not first).
  const double nu = 0.3;
  const Material m = unit_shear(nu);
  for (const Point cell : {Point{0, 0, 1.0, 1.0}, Point{0, 0, 1.0, 0.1}, Point{0, 0, 0.1, 1.0}}) {
    const double d = std::max(cell.dx, cell.dy);
    const double area = cell.dx * cell.dy;
    for (const double angle : {0.4, 1.1, 2.5, -2.0}) {
      std::array<double, 3> previous{};
      for (const double ratio : {25.0, 50.0, 100.0, 200.0, 1000.0}) {
        const double r = ratio * d;
        const double x = r * std::cos(angle);
        const double y = r * std::sin(angle);
        const CerrutiCoefficients c = cerruti_influence(x, y, cell.dx, cell.dy, m);
        const std::array<double, 3> error = {std::abs(c.xx / (area * kernel_xx(x, y, nu)) - 1.0),
                                             std::abs(c.yx / (area * kernel_yx(x, y, nu)) - 1.0),
                                             std::abs(c.zx / (area * kernel_zx(x, y, nu)) - 1.0)};
        INFO("dx = " << cell.dx << ", dy = " << cell.dy << ", angle = " << angle
                     << ", r/d = " << ratio);
        for (std::size_t k = 0; k < 3; ++k) {
          INFO("component " << k << ": relative error " << error[k]);
          CHECK(error[k] < 0.5 / (ratio * ratio));
          // At least second order (zx falls 16-fold for square cells: x/r^2 is harmonic, and the
          // (d/r)^2 term is (a^2/6) times its Laplacian).
          if (ratio == 50.0) CHECK(previous[k] / error[k] > 3.8);
        }
        previous = error;
      }
    }
  }
}

TEST_CASE("cerruti_influence has the exact symmetries of its kernels and signs of its physics",
          "[convolution][cerruti]") {
  // xx even in x and y; yx odd in both; zx odd in x, even in y: bit for bit (every form is
  // evaluated in the first quadrant). Points in the closed form and in every far-field rule.
  const Material m(2.1e11, 0.29);
  for (const Point& p : field_points()) {
    for (const double scale : {1.0, 1e-4}) {  // cells of metres and of 0.1 mm
      const double x = p.x * scale;
      const double y = p.y * scale;
      const double dx = p.dx * scale;
      const double dy = p.dy * scale;
      INFO("x = " << x << ", y = " << y << ", dx = " << dx << ", dy = " << dy);
      const CerrutiCoefficients c = cerruti_influence(x, y, dx, dy, m);
      const CerrutiCoefficients mx = cerruti_influence(-x, y, dx, dy, m);
      const CerrutiCoefficients my = cerruti_influence(x, -y, dx, dy, m);
      const CerrutiCoefficients mxy = cerruti_influence(-x, -y, dx, dy, m);
      CHECK(mx.xx == c.xx);
      CHECK(my.xx == c.xx);
      CHECK(mxy.xx == c.xx);
      CHECK(mx.yx == -c.yx);
      CHECK(my.yx == -c.yx);
      CHECK(mxy.yx == c.yx);
      CHECK(mx.zx == -c.zx);
      CHECK(my.zx == c.zx);
      // u_x follows the load everywhere; u_y points away from the load's line of action ahead of
      // it and towards it behind (yx > 0 for x y > 0); ahead of the load the surface moves into
      // the body (zx > 0 for x > 0).
      CHECK(c.xx > 0.0);
      if (x == 0.0) CHECK(c.zx == 0.0);
      if (x == 0.0 || y == 0.0) CHECK(c.yx == 0.0);
      if (x > 0.0) CHECK(c.zx > 0.0);
      if (x * y > 0.0) CHECK(c.yx > 0.0);
      // Reciprocity of the tangential pair (K_xy(x) = K_yx(-x), and yx is even under x -> -x):
      // the (x, y) coefficient, yx with the axes swapped, equals yx. Same sums in another order.
      CHECK(cerruti_influence(y, x, dy, dx, m).yx == Approx(c.yx).epsilon(1e-15).margin(0.0));
      // Units: linear in 1/mu.
      CHECK(cerruti_influence(x, y, dx, dy, unit_shear(0.29)).xx * (1.0 / m.shear_modulus()) ==
            Approx(c.xx).epsilon(1e-15));
    }
  }
}

TEST_CASE(
    "cerruti_influence: zx is minus u_x under a uniform pressure (Betti), checked by quadrature",
    "[convolution][cerruti]") {
  // Betti's theorem between q_x on a cell and a unit pressure on the same cell gives
  // K_xz(x) = K_zx(-x) = -K_zx(x): u_x under the pressure is -zx at the same point. The reference
  // integrates Boussinesq's u_r (towards the load) in polar coordinates: it shares no formula with
  // Cerruti's u_z, so it also checks zx's sign. Polar QAG at 2e-14 on a piecewise-smooth
  // integrand; measured differences <= 6.1e-14 (the polar integral cancels where zx is small:
  // near the axis x = 0 and far away), 1e-12 as in the first test case.
  for (const double nu : {0.3, 0.1}) {
    const Material m = unit_shear(nu);
    for (const Point& p : field_points()) {
      INFO("nu = " << nu << ", x = " << p.x << ", y = " << p.y << ", dx = " << p.dx
                   << ", dy = " << p.dy);
      const double ux = pressure_ux_polar(p.x, p.y, p.dx, p.dy, nu);
      const double zx = cerruti_influence(p.x, p.y, p.dx, p.dy, m).zx;
      CHECK(-zx == Approx(ux).epsilon(1e-12).margin(1e-15));
      if (p.x > 0.0) CHECK(ux < 0.0);  // a pressure pulls the surface towards the load
    }
  }
}

TEST_CASE("cerruti_influence summed over a uniform patch equals the patch's own coefficient",
          "[convolution][cerruti]") {
  // Linearity: the coefficients of the cells of an nx x ny patch, summed at a cell centre, are the
  // coefficient of the patch. The sum mixes the closed forms and every far-field rule (cells up to
  // ~40 sizes away), the patch value is one closed form. Measured <= 3.8e-15 relative (xx),
  // 5.7e-16 (yx), 5e-16 (zx); 1e-13 allows the roundoff of 1025 terms, each within ~1e-14.
  const Material m = unit_shear(0.3);
  const double dx = 1e-3;
  const double dy = 0.5e-3;
  const int nx = 41;
  const int ny = 25;
  for (const std::array<int, 2> at :
       {std::array<int, 2>{0, 0}, std::array<int, 2>{7, -4}, std::array<int, 2>{-20, 12}}) {
    const double x = at[0] * dx;
    const double y = at[1] * dy;
    CerrutiCoefficients sum;
    for (int j = -(ny / 2); j <= ny / 2; ++j) {
      for (int i = -(nx / 2); i <= nx / 2; ++i) {
        const CerrutiCoefficients c = cerruti_influence(x - i * dx, y - j * dy, dx, dy, m);
        sum.xx += c.xx;
        sum.yx += c.yx;
        sum.zx += c.zx;
      }
    }
    const CerrutiCoefficients patch = cerruti_influence(x, y, nx * dx, ny * dy, m);
    INFO("at cell (" << at[0] << ", " << at[1] << ")");
    CHECK(sum.xx == Approx(patch.xx).epsilon(1e-13).margin(0.0));
    CHECK(sum.yx == Approx(patch.yx).epsilon(1e-13).margin(1e-16 * patch.xx));
    CHECK(sum.zx == Approx(patch.zx).epsilon(1e-13).margin(1e-16 * patch.xx));
  }
  // The centre of a 2A x 2B rectangle: u_x = 2 [B asinh(A/B) + (1 - nu) A asinh(B/A)]/(pi mu),
  // (1.5b) with the four corners equal; u_y = u_z = 0.
  const double A = 0.5 * nx * dx;
  const double B = 0.5 * ny * dy;
  const CerrutiCoefficients centre = cerruti_influence(0.0, 0.0, 2 * A, 2 * B, m);
  CHECK(centre.xx ==
        Approx(2.0 * (B * std::asinh(A / B) + 0.7 * A * std::asinh(B / A)) / pi).epsilon(1e-15));
  CHECK(centre.yx == 0.0);
  CHECK(centre.zx == 0.0);
}

TEST_CASE("cerruti_influence over a disk of cells tends to the uniformly sheared disk",
          "[convolution][cerruti]") {
  // u_x at the centre of a disk of radius c under a uniform q_x: the point force integrated in
  // polar coordinates, \int_0^2pi [(1 - nu) + nu cos^2 phi] dphi c/(2 pi mu) = (2 - nu) q c/(2 mu).
  // (pi (2 - nu) q0 c/(4 mu), pi/2 times larger, is the centre value under
  // q0 (1 - r^2/c^2)^(-1/2), Johnson's (1985) traction of a bonded disk: the same polar integral
  // with that weight, \int_0^c (1 - r^2/c^2)^(-1/2) dr = pi c/2; not a uniform q.) The formula is
  // checked by quadrature first. The cells whose
  // centres lie in the disk (N of them, side h) cover a staircase whose area differs from pi c^2
  // by a few cells, erratically with c/h (the Gauss circle problem): compared at the radius of
  // equal area, c_eff = h sqrt(N/pi), the sum converges like (h/c)^2, measured
  // 5.6e-4, 1.2e-4, 2.8e-5, 7.1e-6 relative at c/h = 10, 20, 40, 80 (0.045 to 0.056 (h/c)^2):
  // bound 0.1 (h/c)^2.
  const double nu = 0.3;
  const Material m = unit_shear(nu);
  const coatfft::detail::GslHandlerOff quiet;
  auto ws = coatfft::detail::make_gsl_workspace(100);
  const double radius = 1.0;
  const auto integral = coatfft::detail::gsl_qag(
      [nu](double phi) { return (1.0 - nu) + nu * std::cos(phi) * std::cos(phi); }, 0.0, 2.0 * pi,
      0.0, 1e-13, GSL_INTEG_GAUSS21, ws.get());
  REQUIRE(integral.status == GSL_SUCCESS);
  const double disk = (2.0 - nu) * radius / 2.0;  // mu = 1 Pa, q = 1 Pa
  CHECK(integral.value * radius / (2.0 * pi) == Approx(disk).epsilon(1e-14));
  CHECK(std::abs(pi * (2.0 - nu) * radius / 4.0 / disk - 1.0) > 0.5);  // off by pi/2
  for (const int cells_per_radius : {20, 40}) {
    const double h = radius / cells_per_radius;
    double sum = 0.0;
    double sum_zx = 0.0;
    int count = 0;
    for (int j = -cells_per_radius; j <= cells_per_radius; ++j) {
      for (int i = -cells_per_radius; i <= cells_per_radius; ++i) {
        if (std::hypot(i * h, j * h) > radius) continue;
        const CerrutiCoefficients c = cerruti_influence(-i * h, -j * h, h, h, m);
        sum += c.xx;
        sum_zx += c.zx;
        ++count;
      }
    }
    const double equal_area = h * std::sqrt(count / pi);
    const double expected = (2.0 - nu) * equal_area / 2.0;
    INFO("c/h = " << cells_per_radius << ": relative error " << sum / expected - 1.0);
    CHECK(std::abs(sum / expected - 1.0) < 0.1 / (cells_per_radius * cells_per_radius));
    CHECK(std::abs(sum_zx) < 1e-14 * sum);  // odd in x over a symmetric set of cells
  }
}

TEST_CASE("cerruti_influence refuses bad cells and points", "[convolution][cerruti][bad_input]") {
  const Material m(2e11, 0.3);
  CHECK_THROWS_AS(cerruti_influence(0.0, 0.0, 0.0, 1.0, m), coatfft::InvalidArgument);
  CHECK_THROWS_AS(cerruti_influence(0.0, 0.0, 1.0, -1.0, m), coatfft::InvalidArgument);
  CHECK_THROWS_AS(cerruti_influence(0.0, 0.0, INFINITY, 1.0, m), coatfft::InvalidArgument);
  CHECK_THROWS_AS(cerruti_influence(std::nan(""), 0.0, 1.0, 1.0, m), coatfft::InvalidArgument);
  CHECK_THROWS_AS(cerruti_influence(0.0, INFINITY, 1.0, 1.0, m), coatfft::InvalidArgument);
}
