// Love's influence coefficient (theory.md 1.3) against an independent quadrature of the Boussinesq
// kernel 1/(pi R) over the rectangle, the closed-form self term and the far-field expansion.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "convolution/influence_kernel.hpp"
#include "convolution/love_influence.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"

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
    // Closed form of theory.md 1.3; both sides are a few roundings apart.
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
  CHECK_THROWS_AS(coatfft::InfluenceKernel(grid, coatfft::Field::Zero(10, 7)),
                  coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::love_kernel(grid, 0.0), coatfft::InvalidArgument);
}
