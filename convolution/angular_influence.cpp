#include "convolution/angular_influence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/detail/gauss_legendre.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// docs/theory.md (2.9.3). All lengths in units of the larger cell side, field point in the first
// quadrant (the caller restores the parities). R = sqrt(X^2 + Y^2 + beta^2).

// \int d_x psi dY = X asinh(Y/sqrt(X^2 + beta^2)) - beta atan(X Y (R - beta)/(X^2 R + Y^2 beta)),
// each term 0 where its prefactor is (its limit; the atan's argument stays finite elsewhere).
double first_antiderivative(double X, double Y, double beta) {
  if (X == 0.0) return 0.0;
  const double R = std::sqrt(X * X + Y * Y + beta * beta);
  double f = X * std::asinh(Y / std::sqrt(X * X + beta * beta));
  if (beta > 0.0) f -= beta * std::atan2(X * Y * (R - beta), X * X * R + Y * Y * beta);
  return f;
}

// psi = R - beta ln(R + beta), whose corner sum is the cell integral of d_xy psi.
double psi(double X, double Y, double beta) {
  const double R = std::sqrt(X * X + Y * Y + beta * beta);
  return beta > 0.0 ? R - beta * std::log(R + beta) : R;
}

// \int ln(R + beta) dY = Y ln(R + beta) + X atan(X Y (R - beta)/(X^2 R + Y^2 beta))
//   + beta asinh(Y/sqrt(X^2 + beta^2)), less the term -Y, which every corner sum cancels.
double log_antiderivative(double X, double Y, double beta) {
  const double R = std::sqrt(X * X + Y * Y + beta * beta);
  double f = 0.0;
  if (Y != 0.0) f += Y * std::log(R + beta);
  if (X != 0.0) f += X * std::atan2(X * Y * (R - beta), X * X * R + Y * Y * beta);
  if (beta > 0.0) f += beta * std::asinh(Y / std::sqrt(X * X + beta * beta));
  return f;
}

template <class F>
double corner_sum(F f, double x, double y, double a, double b) {
  return f(x + a, y + b) - f(x + a, y - b) - f(x - a, y + b) + f(x - a, y - b);
}

AngularCoefficients closed_form(double x, double y, double a, double b, double beta) {
  const auto along_x = [beta](double X, double Y) { return first_antiderivative(X, Y, beta); };
  const auto along_y = [beta](double X, double Y) { return first_antiderivative(Y, X, beta); };
  const auto potential = [beta](double X, double Y) { return psi(X, Y, beta); };
  const auto logarithm = [beta](double X, double Y) { return log_antiderivative(X, Y, beta); };
  return {(corner_sum(along_x, x, y, a, b) - corner_sum(along_y, x, y, a, b)) / kTwoPi,
          corner_sum(potential, x, y, a, b) / std::numbers::pi,
          corner_sum(logarithm, x, y, a, b) / kTwoPi};
}

// The point kernels, analytic over the cell far from it: an N x N Gauss-Legendre product rule.
template <int N>
AngularCoefficients gauss_legendre_rule(double x, double y, double a, double b, double beta) {
  const auto& rule = detail::gauss_legendre<N>();
  AngularCoefficients sum;
  for (std::size_t p = 0; p < N; ++p)
    for (std::size_t q = 0; q < N; ++q) {
      const double X = x - a * rule.nodes[p];
      const double Y = y - b * rule.nodes[q];
      const double R = std::sqrt(X * X + Y * Y + beta * beta);
      const double w = rule.weights[p] * rule.weights[q] / (R * (R + beta));
      sum.cos2 += w * (Y * Y - X * X) / (R + beta);
      sum.sin2 += w * X * Y / (R + beta);
      sum.cos1 += w * X;
    }
  const double area = a * b;  // the weights sum to 2 per axis: (2a)(2b)/4
  return {area * sum.cos2 / kTwoPi, -area * sum.sin2 / std::numbers::pi, area * sum.cos1 / kTwoPi};
}

// The rule order for rho^2 = x^2 + y^2 + beta^2 in units of the larger side: the switch distances
// of Cerruti's coefficients (convolution/cerruti_influence.cpp), whose kernels have the same
// analytic structure at beta = 0 and are smoother for beta > 0 (nearest singularity at distance
// rho in the complex plane).
AngularCoefficients far_field(double rho2, double x, double y, double a, double b, double beta) {
  if (rho2 >= 4096.0 * 4096.0) return gauss_legendre_rule<2>(x, y, a, b, beta);
  if (rho2 >= 256.0 * 256.0) return gauss_legendre_rule<3>(x, y, a, b, beta);
  if (rho2 >= 48.0 * 48.0) return gauss_legendre_rule<4>(x, y, a, b, beta);
  if (rho2 >= 12.0 * 12.0) return gauss_legendre_rule<5>(x, y, a, b, beta);
  return gauss_legendre_rule<6>(x, y, a, b, beta);
}

}  // namespace

AngularCoefficients angular_influence(double x, double y, double dx, double dy, double beta) {
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0,
                  "angular_influence: the cell (", dx, " x ", dy, " m) must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(x) && std::isfinite(y), "angular_influence: (x, y) = (", x, ", ", y,
                  ") m, but both must be finite");
  COATFFT_REQUIRE(std::isfinite(beta) && beta >= 0, "angular_influence: beta = ", beta,
                  " m, but it must be finite and >= 0");
  const double d = std::max(dx, dy);
  const double xs = std::abs(x) / d;
  const double ys = std::abs(y) / d;
  const double bs = beta / d;
  const double a = 0.5 * dx / d;
  const double b = 0.5 * dy / d;
  const double rho2 = xs * xs + ys * ys + bs * bs;
  const AngularCoefficients c =
      rho2 < 64.0 ? closed_form(xs, ys, a, b, bs) : far_field(rho2, xs, ys, a, b, bs);
  const double sign_x = std::signbit(x) ? -1.0 : 1.0;
  const double sign_y = std::signbit(y) ? -1.0 : 1.0;
  return {d * c.cos2, sign_x * sign_y * d * c.sin2, sign_x * d * c.cos1};
}

}  // namespace coatfft
