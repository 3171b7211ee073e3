// The cell integrals of the angular kernels (docs/theory.md 2.9.3) against independent
// references: an adaptive 2-D quadrature of the point kernels over the cell (beta > 0, where they
// are smooth), Cerruti's coefficients of the homogeneous half-space (beta = 0: the combinations
// S/k + D cos(2 theta)/k, D sin(2 theta)/k and C cos(theta)/k of docs/theory.md (2.9.1)), and the
// switch between the closed forms and the far-field rule.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <numbers>

#include "convolution/kernels/angular_influence.hpp"
#include "convolution/kernels/cerruti_influence.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "core/detail/gsl_quadrature.hpp"
#include "core/error.hpp"
#include "materials/material.hpp"

using coatfft::angular_influence;
using coatfft::AngularCoefficients;

namespace {

using std::numbers::pi;

// The point kernels of docs/theory.md (2.9.2) and, flat, (2.9.6), R = sqrt(X^2 + Y^2 + beta^2),
// written from the Hankel transforms \int exp(-beta k) J_n(kr) k^m dk (m = 0, 1) directly.
AngularCoefficients point_kernels(double X, double Y, double beta, bool flat = false) {
  const double r2 = X * X + Y * Y, R = std::sqrt(r2 + beta * beta);
  if (r2 == 0.0) return {0.0, 0.0, 0.0};  // every kernel vanishes at r = 0 for beta > 0
  // (R - beta)^n/(r^n R) and (R - beta)^n (n R + beta)/(r^n R^3), as functions of r^2 > 0.
  const double q = (R - beta) * (R - beta) / r2;  // ((R - beta)/r)^2
  if (flat)
    return {-(X * X - Y * Y) / r2 * q * (2 * R + beta) / (2 * pi * R * R * R),
            -2 * X * Y / r2 * q * (2 * R + beta) / (2 * pi * R * R * R),
            X / r2 * (R - beta) * (R + beta) / (2 * pi * R * R * R)};
  return {-(X * X - Y * Y) / r2 * q / (2 * pi * R), -2 * X * Y / r2 * q / (2 * pi * R),
          X / r2 * (R - beta) / (2 * pi * R)};
}

// Nested GSL QAG (61-point Gauss-Kronrod) over the cell: for beta > 0 the kernels are analytic on
// the real plane, so the plain rule converges to its tolerance 1e-13.
double cell_quadrature(const std::function<double(double, double)>& f, double dx, double dy) {
  const coatfft::detail::GslHandlerOff quiet;
  auto inner_ws = coatfft::detail::make_gsl_workspace(200);
  auto outer_ws = coatfft::detail::make_gsl_workspace(200);
  const auto inner = [&](double yp) {
    return coatfft::detail::gsl_qag([&](double xp) { return f(xp, yp); }, -0.5 * dx, 0.5 * dx,
                                    1e-20, 1e-13, GSL_INTEG_GAUSS61, inner_ws.get())
        .value;
  };
  const auto r = coatfft::detail::gsl_qag(inner, -0.5 * dy, 0.5 * dy, 1e-20, 1e-13,
                                          GSL_INTEG_GAUSS61, outer_ws.get());
  return r.value;
}

AngularCoefficients reference(double x, double y, double dx, double dy, double beta, bool flat) {
  AngularCoefficients c;
  c.cos2 = cell_quadrature(
      [&](double xp, double yp) { return point_kernels(x - xp, y - yp, beta, flat).cos2; }, dx, dy);
  c.sin2 = cell_quadrature(
      [&](double xp, double yp) { return point_kernels(x - xp, y - yp, beta, flat).sin2; }, dx, dy);
  c.cos1 = cell_quadrature(
      [&](double xp, double yp) { return point_kernels(x - xp, y - yp, beta, flat).cos1; }, dx, dy);
  return c;
}

}  // namespace

TEST_CASE("angular kernels with beta > 0 equal the quadrature of their point forms",
          "[angular_influence]") {
  // Cells 1 x 1 and 1 x 0.3 (m-free units), beta from a fifth of a cell to three cells, field
  // points on the cell, on its edge, near and far (both sides of the switch at 8 cells).
  const double cells[][2] = {{1.0, 1.0}, {1.0, 0.3}, {0.4, 1.0}};
  const double betas[] = {0.2, 1.0, 3.0};
  const double points[][2] = {{0.0, 0.0},  {0.5, 0.15}, {0.3, 0.7}, {1.7, -2.2},
                              {-5.0, 3.0}, {7.9, 0.4},  {8.2, 1.0}, {-20.0, 13.0}};
  double worst = 0.0;
  for (const auto& cell : cells)
    for (double beta : betas)
      for (const auto& p : points) {
        const AngularCoefficients got = angular_influence(p[0], p[1], cell[0], cell[1], beta);
        const AngularCoefficients ref = reference(p[0], p[1], cell[0], cell[1], beta, false);
        // Scale: the size of the coefficients near the cell, area / (2 pi max(rho, d)).
        const double scale =
            cell[0] * cell[1] / (2.0 * pi * std::max(std::hypot(p[0], p[1], beta), 1.0));
        for (double e : {got.cos2 - ref.cos2, got.sin2 - ref.sin2, got.cos1 - ref.cos1})
          worst = std::isnan(e) || std::abs(e) / scale > worst ? std::abs(e) / scale : worst;
      }
  // The corner sums lose about log10((rho/d)^2) digits near the switch at 8 cells.
  CHECK(std::isfinite(worst));
  CHECK(worst < 1e-11);
}

TEST_CASE("flat angular kernels equal the quadrature of their point forms", "[angular_influence]") {
  // The k^0 family (2.9.6): kernels of size area/(2 pi rho^2) near the cell; the same cells,
  // betas and points as above.
  const double cells[][2] = {{1.0, 1.0}, {1.0, 0.3}, {0.4, 1.0}};
  const double points[][2] = {{0.0, 0.0},  {0.5, 0.15}, {0.3, 0.7}, {1.7, -2.2},
                              {-5.0, 3.0}, {7.9, 0.4},  {8.2, 1.0}, {-20.0, 13.0}};
  double worst = 0.0;
  for (const auto& cell : cells)
    for (double beta : {0.2, 1.0, 3.0})
      for (const auto& p : points) {
        const AngularCoefficients got =
            coatfft::angular_flat_influence(p[0], p[1], cell[0], cell[1], beta);
        const AngularCoefficients ref = reference(p[0], p[1], cell[0], cell[1], beta, true);
        const double rho2 = p[0] * p[0] + p[1] * p[1] + beta * beta;
        const double scale = cell[0] * cell[1] / (2.0 * pi * std::max(rho2, 1.0));
        for (double e : {got.cos2 - ref.cos2, got.sin2 - ref.sin2, got.cos1 - ref.cos1})
          worst = std::isnan(e) || std::abs(e) / scale > worst ? std::abs(e) / scale : worst;
      }
  CHECK(std::isfinite(worst));
  CHECK(worst < 1e-11);
  CHECK_THROWS_AS(coatfft::angular_flat_influence(0.0, 0.0, 1.0, 1.0, 0.0),
                  coatfft::InvalidArgument);
}

TEST_CASE("angular kernels at beta = 0 combine into Cerruti's coefficients",
          "[angular_influence]") {
  // For mu = 1 Pa the half-space has S = (2 - nu)/2, D = -nu/2, C = (1 - 2 nu)/2 (docs/theory.md
  // (2.9.1)): u_x = S/k + D cos(2 theta)/k, u_y = D sin(2 theta)/k, u_z = -i C cos(theta)/k per
  // unit q_x. Love's coefficient is the cell integral of 1/(pi r) (E* = 1): that of 1/(2 pi r) is
  // half of it.
  const double nu = 0.3;
  const coatfft::Material unit_shear(2.0 * (1.0 + nu), nu);
  const double S = (2.0 - nu) / 2.0, D = -nu / 2.0, C = (1.0 - 2.0 * nu) / 2.0;
  double worst = 0.0;
  for (const auto& cell : {std::array<double, 2>{1.0, 1.0}, std::array<double, 2>{1.0, 0.25}})
    for (double x : {0.0, 0.5, 1.0, 3.0, 7.5, 8.5, 40.0, 300.0})
      for (double y : {0.0, 0.125, 2.0, 9.0, -60.0}) {
        const auto q = coatfft::cerruti_influence(x, y, cell[0], cell[1], unit_shear);
        const AngularCoefficients a = angular_influence(x, y, cell[0], cell[1], 0.0);
        const double l0 = 0.5 * coatfft::love_influence(x, y, cell[0], cell[1]);
        const double scale = std::abs(q.xx);
        worst =
            std::max({worst, std::abs(S * l0 + D * a.cos2 - q.xx) / scale,
                      std::abs(D * a.sin2 - q.yx) / scale, std::abs(C * a.cos1 - q.zx) / scale});
      }
  CHECK(worst < 1e-13);
}

TEST_CASE("angular kernels: parities and bad arguments", "[angular_influence]") {
  const AngularCoefficients a = angular_influence(1.3, 0.7, 1.0, 0.5, 0.4);
  const AngularCoefficients b = angular_influence(-1.3, 0.7, 1.0, 0.5, 0.4);
  const AngularCoefficients c = angular_influence(1.3, -0.7, 1.0, 0.5, 0.4);
  CHECK(b.cos2 == a.cos2);
  CHECK(b.sin2 == -a.sin2);
  CHECK(b.cos1 == -a.cos1);
  CHECK(c.cos2 == a.cos2);
  CHECK(c.sin2 == -a.sin2);
  CHECK(c.cos1 == a.cos1);
  CHECK_THROWS_AS(angular_influence(0.0, 0.0, 0.0, 1.0, 0.1), coatfft::InvalidArgument);
  CHECK_THROWS_AS(angular_influence(0.0, 0.0, 1.0, 1.0, -0.1), coatfft::InvalidArgument);
  CHECK_THROWS_AS(angular_influence(NAN, 0.0, 1.0, 1.0, 0.1), coatfft::InvalidArgument);
}
