#include "convolution/kernels/angular_influence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/detail/gauss_legendre.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

using std::numbers::pi;

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

AngularCoefficients angular_closed_form(double x, double y, double a, double b, double beta) {
  const auto along_x = [beta](double X, double Y) { return first_antiderivative(X, Y, beta); };
  const auto along_y = [beta](double X, double Y) { return first_antiderivative(Y, X, beta); };
  const auto potential = [beta](double X, double Y) { return psi(X, Y, beta); };
  const auto logarithm = [beta](double X, double Y) { return log_antiderivative(X, Y, beta); };
  return {(corner_sum(along_x, x, y, a, b) - corner_sum(along_y, x, y, a, b)) / (2.0 * pi),
          corner_sum(potential, x, y, a, b) / std::numbers::pi,
          corner_sum(logarithm, x, y, a, b) / (2.0 * pi)};
}

// (2.9.6): \int d_x ln(R + beta) dY = atan(X Y (R - beta)/(X^2 R + Y^2 beta)) (0 at X = 0).
double flat_antiderivative(double X, double Y, double beta) {
  const double R = std::sqrt(X * X + Y * Y + beta * beta);
  return std::atan2(X * Y * (R - beta), X * X * R + Y * Y * beta);
}

AngularCoefficients flat_closed_form(double x, double y, double a, double b, double beta) {
  const auto along_x = [beta](double X, double Y) { return flat_antiderivative(X, Y, beta); };
  const auto along_y = [beta](double X, double Y) { return flat_antiderivative(Y, X, beta); };
  const auto logarithm = [beta](double X, double Y) {
    return std::log(std::sqrt(X * X + Y * Y + beta * beta) + beta);
  };
  const auto inverse = [beta](double X, double Y) {
    return std::asinh(Y / std::sqrt(X * X + beta * beta));
  };
  return {(corner_sum(along_x, x, y, a, b) - corner_sum(along_y, x, y, a, b)) / (2.0 * pi),
          corner_sum(logarithm, x, y, a, b) / std::numbers::pi,
          -corner_sum(inverse, x, y, a, b) / (2.0 * pi)};
}

// The point kernels, analytic over the cell far from it: an N x N Gauss-Legendre product rule.
// The point kernels of (2.9.2) (flat = false) or (2.9.6) (flat = true) at (X, Y), times 2 pi.
AngularCoefficients point_kernels(double X, double Y, double beta, bool flat) {
  const double R = std::sqrt(X * X + Y * Y + beta * beta);
  if (flat) {
    const double w = (2.0 * R + beta) / (R * R * R * (R + beta) * (R + beta));
    return {w * (Y * Y - X * X), -2.0 * w * X * Y, X / (R * R * R)};
  }
  const double w = 1.0 / (R * (R + beta) * (R + beta));
  return {w * (Y * Y - X * X), -2.0 * w * X * Y, X / (R * (R + beta))};
}

template <int N>
AngularCoefficients gauss_legendre_rule(double x, double y, double a, double b, double beta,
                                        bool flat) {
  const auto& rule = detail::gauss_legendre<N>();
  AngularCoefficients sum;
  for (std::size_t p = 0; p < N; ++p)
    for (std::size_t q = 0; q < N; ++q) {
      const AngularCoefficients k =
          point_kernels(x - a * rule.nodes[p], y - b * rule.nodes[q], beta, flat);
      const double w = rule.weights[p] * rule.weights[q];
      sum.cos2 += w * k.cos2;
      sum.sin2 += w * k.sin2;
      sum.cos1 += w * k.cos1;
    }
  const double scale = a * b / (2.0 * pi);  // the weights sum to 2 per axis: (2a)(2b)/4
  return {scale * sum.cos2, scale * sum.sin2, scale * sum.cos1};
}

// The rule order for rho^2 = x^2 + y^2 + beta^2 in units of the larger side: the switch distances
// of Cerruti's coefficients (convolution/kernels/cerruti_influence.cpp), whose kernels have the
// same analytic structure at beta = 0 and are smoother for beta > 0 (nearest singularity at
// distance rho in the complex plane).
AngularCoefficients far_field(double rho2, double x, double y, double a, double b, double beta,
                              bool flat) {
  if (rho2 >= 4096.0 * 4096.0) return gauss_legendre_rule<2>(x, y, a, b, beta, flat);
  if (rho2 >= 256.0 * 256.0) return gauss_legendre_rule<3>(x, y, a, b, beta, flat);
  if (rho2 >= 48.0 * 48.0) return gauss_legendre_rule<4>(x, y, a, b, beta, flat);
  if (rho2 >= 12.0 * 12.0) return gauss_legendre_rule<5>(x, y, a, b, beta, flat);
  return gauss_legendre_rule<6>(x, y, a, b, beta, flat);
}

// Both families: lengths in units of the larger side, the first quadrant, the parities restored.
AngularCoefficients evaluate(double x, double y, double dx, double dy, double beta, bool flat) {
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0,
                  "angular_influence: the cell (", dx, " x ", dy, " m) must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(x) && std::isfinite(y), "angular_influence: (x, y) = (", x, ", ", y,
                  ") m, but both must be finite");
  COATFFT_REQUIRE(std::isfinite(beta) && (flat ? beta > 0 : beta >= 0),
                  "angular_influence: beta = ", beta, " m, but it must be finite and ",
                  flat ? "> 0" : ">= 0");
  const double d = std::max(dx, dy);
  const double xs = std::abs(x) / d;
  const double ys = std::abs(y) / d;
  const double bs = beta / d;
  const double a = 0.5 * dx / d;
  const double b = 0.5 * dy / d;
  const double rho2 = xs * xs + ys * ys + bs * bs;
  AngularCoefficients c;
  if (rho2 >= 64.0)
    c = far_field(rho2, xs, ys, a, b, bs, flat);
  else
    c = flat ? flat_closed_form(xs, ys, a, b, bs) : angular_closed_form(xs, ys, a, b, bs);
  // The 1/k family scales with the length d, the flat one is dimensionless.
  const double scale = flat ? 1.0 : d;
  const double sign_x = std::signbit(x) ? -1.0 : 1.0;
  const double sign_y = std::signbit(y) ? -1.0 : 1.0;
  return {scale * c.cos2, sign_x * sign_y * scale * c.sin2, sign_x * scale * c.cos1};
}

}  // namespace

AngularCoefficients angular_influence(double x, double y, double dx, double dy, double beta) {
  return evaluate(x, y, dx, dy, beta, false);
}

AngularCoefficients angular_flat_influence(double x, double y, double dx, double dy, double beta) {
  return evaluate(x, y, dx, dy, beta, true);
}

}  // namespace coatfft
