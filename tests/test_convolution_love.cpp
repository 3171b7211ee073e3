// Love's influence coefficient (docs/theory.md 1.3) against an independent quadrature of the
// Boussinesq kernel 1/(pi R) over the rectangle, the closed-form self term and the far-field
// expansion.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/direct_operator.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/norms.hpp"
#include "long_double_gauss_legendre.hpp"

using coatfft::love_influence;

namespace {

struct Rectangle {
  double x, y, a, b;  // field point and half sides
};

// Length of the part of the ray from (x, y) along theta that lies in the rectangle (slab method).
double chord(double theta, void* params) {
  const auto& q = *static_cast<const Rectangle*>(params);
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  const std::array<double, 2> origin = {q.x, q.y};
  const std::array<double, 2> dir = {c, s};
  const std::array<double, 2> half = {q.a, q.b};
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

// Independent reference: in polar coordinates about the field point the Boussinesq integrand
// 1/(pi R) times the area element R dR dtheta is 1/pi, so u = (1/pi) * integral over theta of the
// chord length; the theta integral is done numerically by GSL QAGP with breakpoints at the
// corner directions, where the chord has kinks.
double polar_quadrature(double x, double y, double dx, double dy) {
  Rectangle q{x, y, 0.5 * dx, 0.5 * dy};
  std::vector<double> points;
  const double base = -std::numbers::pi;
  for (double cx : {-q.a, q.a}) {
    for (double cy : {-q.b, q.b}) {
      if (cx == x && cy == y) continue;
      points.push_back(std::atan2(cy - y, cx - x));
    }
  }
  points.push_back(base);
  points.push_back(std::numbers::pi);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  gsl_function f{&chord, &q};
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(2000);
  double result = 0.0;
  double abserr = 0.0;
  gsl_set_error_handler_off();
  const int status = gsl_integration_qagp(&f, points.data(), points.size(), 0.0, 2e-14, 2000, ws,
                                          &result, &abserr);
  gsl_integration_workspace_free(ws);
  REQUIRE(status == GSL_SUCCESS);
  return result / std::numbers::pi;
}

}  // namespace

TEST_CASE("love_influence equals a polar quadrature of 1/(pi R) over the rectangle",
          "[convolution][love]") {
  struct Case {
    double x, y, dx, dy;
  };
  // Inside, on an edge, at a corner, outside; square and elongated cells; and points beyond
  // 8 cell sizes, where love_influence switches to its Gauss-Legendre branch.
  const std::vector<Case> cases = {
      {0.0, 0.0, 1.0, 1.0},  {0.2, 0.1, 1.0, 1.0},    {0.5, 0.1, 1.0, 1.0},  {0.5, 0.5, 1.0, 1.0},
      {1.3, -0.7, 1.0, 1.0}, {3.0, 2.0, 1.0, 1.0},    {0.3, 0.2, 2.0, 0.5},  {1.0, 0.0, 2.0, 0.5},
      {-2.5, 1.1, 2.0, 0.5}, {0.0, 0.25, 2.0, 0.5},   {7.0, -3.0, 0.1, 3.0}, {7.9, 0.0, 1.0, 1.0},
      {8.1, 0.0, 1.0, 1.0},  {6.0, 5.5, 1.0, 1.0},    {30.0, 2.0, 1.0, 1.0}, {40.0, 10.0, 1.0, 1.0},
      {0.0, 70.0, 2.0, 0.5}, {500.0, 300.0, 1.0, 1.0}};
  for (const auto& c : cases) {
    const double reference = polar_quadrature(c.x, c.y, c.dx, c.dy);
    const double value = love_influence(c.x, c.y, c.dx, c.dy);
    INFO("x = " << c.x << ", y = " << c.y << ", dx = " << c.dx << ", dy = " << c.dy);
    // QAGP at epsrel 2e-14 on a piecewise-smooth integrand; the closed form loses ~64 eps
    // max(dx,dy)/min(dx,dy) to cancellation just inside the 8 d switch. Measured differences
    // are <= 1.1e-14 at these points; 5e-14 leaves margin and still catches any formula slip.
    CHECK(value == Approx(reference).epsilon(5e-14).margin(0.0));
  }
}

TEST_CASE("love_influence self term of a square cell is 4 asinh(1) d / pi", "[convolution][love]") {
  for (double d : {1e-6, 1e-3, 1.0, 7.5}) {
    // Closed form of docs/theory.md 1.3; both sides are a few roundings apart.
    CHECK(love_influence(0.0, 0.0, d, d) ==
          Approx(4.0 * std::asinh(1.0) * d / std::numbers::pi).epsilon(1e-15));
  }
}

TEST_CASE("love_influence tends to the point-load field dx dy/(pi r) far away",
          "[convolution][love]") {
  const double dx = 1.0;
  const double dy = 0.6;
  const double a = 0.5 * dx;
  const double b = 0.5 * dy;
  for (double r : {10.0, 20.0, 100.0, 1000.0}) {
    for (double angle : {0.0, 0.4, 1.1}) {
      const double x = r * std::cos(angle);
      const double y = r * std::sin(angle);
      const double point = dx * dy / (std::numbers::pi * r);
      // Second moment of the rectangle: mean of 1/|r - r'| = 1/r + [a^2 (2x^2 - y^2) +
      // b^2 (2y^2 - x^2)] / (6 r^5) + O(d^4 / r^5).
      const double quadrupole =
          point * (1.0 + (a * a * (2 * x * x - y * y) + b * b * (2 * y * y - x * x)) /
                             (6.0 * std::pow(r, 4)));
      const double u = love_influence(x, y, dx, dy);
      INFO("r = " << r << ", angle = " << angle);
      // Leading error O((d/r)^2) and, with the quadrupole, O((d/r)^4); the bounds below are the
      // coefficient estimates (a^2/3 and a^4 / 5 with a = 0.5) with a margin for roundoff.
      CHECK(std::abs(u / point - 1.0) < 0.1 / (r * r));
      CHECK(std::abs(u / quadrupole - 1.0) < 0.05 / std::pow(r, 4) + 1e-14);
    }
  }
}

TEST_CASE("love_influence refuses non-positive cells", "[convolution][love][bad_input]") {
  CHECK_THROWS_AS(love_influence(0.0, 0.0, 0.0, 1.0), coatfft::InvalidArgument);
  CHECK_THROWS_AS(love_influence(0.0, 0.0, 1.0, -1.0), coatfft::InvalidArgument);
  CHECK_THROWS_AS(love_influence(std::nan(""), 0.0, 1.0, 1.0), coatfft::InvalidArgument);
}

TEST_CASE("love_kernel holds love_influence / E* at every offset, in wrap-around slots",
          "[convolution][love]") {
  const coatfft::Grid grid(5, 4, 5e-3, 2e-3);
  const double e_star = 2.3e11;
  const auto kernel = coatfft::love_kernel(grid, e_star);
  for (std::ptrdiff_t dj = -3; dj <= 3; ++dj) {
    for (std::ptrdiff_t di = -4; di <= 4; ++di) {
      const double expected =
          love_influence(di * grid.dx(), dj * grid.dy(), grid.dx(), grid.dy()) / e_star;
      // love_kernel mirrors the quarter di, dj >= 0; at negative offsets the corner sum is
      // evaluated in another order, so the two agree to rounding only.
      CHECK(kernel.at(di, dj) == Approx(expected).epsilon(1e-14).margin(0.0));
      CHECK(kernel.wrapped()(di >= 0 ? di : 10 + di, dj >= 0 ? dj : 8 + dj) == kernel.at(di, dj));
    }
  }
  CHECK(kernel.wrapped().row(5).isZero(0.0));
  CHECK(kernel.wrapped().col(4).isZero(0.0));
  CHECK_THROWS_AS(kernel.at(5, 0), coatfft::InvalidArgument);
  CHECK_THROWS_AS(kernel.at(0, -4), coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::InfluenceKernel(grid, coatfft::InfluenceKernel::Form::coefficients,
                                           coatfft::Field::Zero(10, 7)),
                  coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::love_kernel(grid, 0.0), coatfft::InvalidArgument);
}

// Reference for the far field: a tensor Gauss-Legendre rule of `n` points per side in long double
// (nodes by Newton's iteration on P_n), independent of love_influence's double-precision tables.
// Beyond 8 cells it converges like (4 r/d)^(-2n), so 20 and 24 points are exact to long double
// rounding (~1e-19), which the test checks by comparing the two.
long double long_double_rule(int n, long double x, long double y, long double a, long double b) {
  const LongDoubleRule rule = long_double_gauss_legendre(n);
  const std::vector<long double>& t = rule.nodes;
  const std::vector<long double>& w = rule.weights;
  long double sum = 0.0L;
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = 0; j < t.size(); ++j) {
      const long double ex = x - a * t[i];
      const long double ey = y - b * t[j];
      sum += w[i] * w[j] / std::sqrt(ex * ex + ey * ey);
    }
  return sum * a * b / std::numbers::pi_v<long double>;
}

TEST_CASE("love_influence is exact on both sides of each far-field rule switch",
          "[convolution][love]") {
  // love_influence changes its Gauss-Legendre order at r = 8, 12, 32, 128 and 4096 max(dx, dy)
  // (n = 6, 5, 4, 3, 2 beyond them; estimated error <= ~1e-16 relative). Just inside and just
  // outside each switch, along an axis (the worst direction) and off-axis, for square and
  // elongated cells, against the long-double rule above. 1e-15 allows the rounding of the sum of
  // up to 36 terms and still catches a rule one order too low at its switch (n = 4 at 8 d:
  // 1.7e-12; n = 2 at 1024 d: 7e-15).
  struct Cell {
    double dx, dy;
  };
  for (const Cell cell : {Cell{1.0, 1.0}, Cell{1.0, 0.3}, Cell{0.3, 1.0}}) {
    const double d = std::max(cell.dx, cell.dy);
    for (double ratio : {8.0, 12.0, 32.0, 128.0, 4096.0}) {
      for (double side : {0.999, 1.001}) {
        for (double angle : {0.0, 0.6, 0.5 * std::numbers::pi}) {
          const double r = side * ratio * d;
          const double x = r * std::cos(angle);
          const double y = r * std::sin(angle);
          INFO("dx = " << cell.dx << ", dy = " << cell.dy << ", r/d = " << r / d
                       << ", angle = " << angle);
          const long double r20 = long_double_rule(20, x, y, 0.5L * cell.dx, 0.5L * cell.dy);
          const long double r24 = long_double_rule(24, x, y, 0.5L * cell.dx, 0.5L * cell.dy);
          REQUIRE(std::abs(r20 / r24 - 1.0L) < 1e-17L);
          // Just inside 8 d the closed form is used, with its cancellation (~64 eps d/min(dx, dy),
          // measured up to 1.1e-14 above): the 5e-14 of the first test case there.
          const double tol = side < 1.0 && ratio == 8.0 ? 5e-14 : 1e-15;
          CHECK(love_influence(x, y, cell.dx, cell.dy) ==
                Approx(static_cast<double>(r24)).epsilon(tol).margin(0.0));
        }
      }
    }
  }
  // And where QAGP is still reliable (8 d, square cell: cf. the table above) the two references
  // agree: love_influence within 5e-14 of the polar quadrature just past the first switch.
  CHECK(love_influence(8.008, 0.0, 1.0, 1.0) ==
        Approx(polar_quadrature(8.008, 0.0, 1.0, 1.0)).epsilon(5e-14).margin(0.0));
}

TEST_CASE("love_influence_row equals love_influence along a row through every rule",
          "[convolution][love]") {
  // The row version (used by love_kernel) runs the same rules vectorised along x; a row of 4200
  // cells crosses all five switches. Same arithmetic per point: agreement to rounding (1e-15,
  // a few ulps in case the compiler contracts differently in its vector and scalar code).
  for (const double dy : {1.0, 0.3, 2.0}) {
    const double dx = 1.0;
    for (const double y : {0.0, 5.0 * dy, 100.0 * dy}) {
      std::vector<double> row(4200);
      coatfft::detail::love_influence_row(y, dx, dy, static_cast<std::ptrdiff_t>(row.size()),
                                          row.data());
      for (std::size_t i = 0; i < row.size(); ++i) {
        INFO("dy = " << dy << ", y = " << y << ", i = " << i);
        REQUIRE(row[i] ==
                Approx(love_influence(static_cast<double>(i) * dx, y, dx, dy)).epsilon(1e-15));
      }
    }
  }
  // Threads share the columns of love_kernel: the result does not depend on their number.
  const coatfft::Grid grid(150, 97, 1.5e-3, 0.8e-3);
  const auto one = coatfft::love_kernel(grid, 2e11, 1);
  const auto three = coatfft::love_kernel(grid, 2e11, 3);
  CHECK((one.wrapped() == three.wrapped()).all());
  CHECK_THROWS_AS(coatfft::love_kernel(grid, 2e11, 0), coatfft::InvalidArgument);
}

// The kernel's spectrum on DC-FFT's padded lattice by the cosine sum of the definition in
// convolution/kernels/influence_kernel.hpp, over every wrapped offset: O((nx ny)^2), independent of
// FFTW.
coatfft::Field cosine_sum_spectrum(const coatfft::InfluenceKernel& k) {
  const std::ptrdiff_t nx = k.grid().nx(), ny = k.grid().ny();
  coatfft::Field s = coatfft::Field::Zero(nx + 1, ny + 1);
  for (std::ptrdiff_t jy = 0; jy <= ny; ++jy)
    for (std::ptrdiff_t jx = 0; jx <= nx; ++jx)
      for (std::ptrdiff_t dj = 1 - ny; dj < ny; ++dj)
        for (std::ptrdiff_t di = 1 - nx; di < nx; ++di)
          s(jx, jy) += k.at(di, dj) * std::cos(M_PI * double(jx * di) / double(nx)) *
                       std::cos(M_PI * double(jy * dj) / double(ny));
  return s;
}

TEST_CASE("DcfftOperator from Love's coefficients and from their spectrum equals direct summation",
          "[convolution][love]") {
  // DC-FFT transforms the coefficient quarter by a DCT-I; the spectrum form skips it. References:
  // the same coefficients' spectrum by a plain cosine sum, and the O(N^4) direct sum of the
  // coefficients, on odd, even, non-square grids with dx != dy.
  struct Shape {
    std::ptrdiff_t nx, ny;
    double lx, ly;
  };
  for (const Shape sh : {Shape{1, 1, 1e-3, 1e-3}, Shape{1, 7, 1e-3, 2e-3}, Shape{7, 1, 3e-3, 1e-3},
                         Shape{31, 33, 2e-3, 2e-3}, Shape{40, 24, 2e-3, 3e-3}}) {
    INFO(sh.nx << " x " << sh.ny);
    const coatfft::Grid g(sh.nx, sh.ny, sh.lx, sh.ly);
    coatfft::Field p(sh.nx, sh.ny);
    for (std::ptrdiff_t j = 0; j < sh.ny; ++j)
      for (std::ptrdiff_t i = 0; i < sh.nx; ++i)
        p(i, j) = 1e6 * (1.0 + std::sin(3.0 * i + 7.0 * j));
    const coatfft::InfluenceKernel kernel = coatfft::love_kernel(g, 1.1e11, 2);
    REQUIRE(kernel.quarter().rows() == sh.nx + 1);
    REQUIRE(kernel.quarter().cols() == sh.ny + 1);
    const coatfft::InfluenceKernel spectrum(g, coatfft::InfluenceKernel::Form::spectrum,
                                            cosine_sum_spectrum(kernel));
    coatfft::DcfftOperator from_quarter(kernel);
    coatfft::DcfftOperator from_spectrum(spectrum);
    coatfft::DirectOperator direct(kernel);
    const coatfft::Field u = from_quarter.apply(p);
    CHECK(coatfft::rel_linf(u, from_spectrum.apply(p)) < 1e-13);
    CHECK(coatfft::rel_linf(u, direct.apply(p)) < 1e-12);
  }
  const coatfft::Grid g(10, 8, 1e-3, 1e-3);
  using Form = coatfft::InfluenceKernel::Form;
  CHECK_THROWS_WITH(coatfft::InfluenceKernel(g, Form::coefficients, coatfft::Field::Ones(10, 8)),
                    Catch::Contains("shape (10, 8)"));
  coatfft::Field bad = coatfft::Field::Ones(11, 9);
  bad(2, 2) = NAN;
  CHECK_THROWS_WITH(coatfft::InfluenceKernel(g, Form::spectrum, bad),
                    Catch::Contains("not finite"));
  CHECK_THROWS_WITH(coatfft::InfluenceKernel(g, Form::spectrum, coatfft::Field::Ones(3, 3)),
                    Catch::Contains("shape (3, 3)"));
  const coatfft::InfluenceKernel spectrum(g, Form::spectrum, coatfft::Field::Ones(11, 9));
  CHECK_THROWS_WITH(spectrum.at(0, 0), Catch::Contains("spectrum"));
  CHECK_THROWS_WITH(coatfft::DirectOperator(spectrum), Catch::Contains("spectrum"));
}
