#include "convolution/love_influence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace coatfft {
namespace {

// F(X, Y) of theory.md (1.5); each term is defined as 0 where its prefactor is 0 (its limit).
double corner(double X, double Y) {
  double f = 0.0;
  if (X != 0.0) f += X * std::asinh(Y / std::abs(X));
  if (Y != 0.0) f += Y * std::asinh(X / std::abs(Y));
  return f;
}

// Far from the rectangle the 4-corner sum cancels: its terms are O(r) while the result is
// O(dx dy / r), so the closed form loses about log10((r/d)^2) digits (1e-10 relative at r = 1000
// d). There 1/R is analytic over the rectangle and a 4 x 4 Gauss-Legendre product rule converges
// like rho^-8 with rho ~ 4 r/d >= 128 here, i.e. to rounding, and costs 16 square roots instead of
// 8 asinh.
constexpr double far_field_ratio = 32.0;

double gauss_legendre_4x4(double x, double y, double a, double b) {
  // Nodes and weights of the 4-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun 25.4.30).
  constexpr std::array<double, 4> t = {-0.861136311594052575, -0.339981043584856265,
                                       0.339981043584856265, 0.861136311594052575};
  constexpr std::array<double, 4> w = {0.347854845137453857, 0.652145154862546143,
                                       0.652145154862546143, 0.347854845137453857};
  double sum = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double ex = x - a * t[i];
    double row = 0.0;
    for (std::size_t j = 0; j < 4; ++j) {
      const double ey = y - b * t[j];
      row += w[j] / std::sqrt(ex * ex + ey * ey);
    }
    sum += w[i] * row;
  }
  return a * b * sum / std::numbers::pi;
}

}  // namespace

double love_influence(double x, double y, double dx, double dy) {
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0, "love_influence: dx = ", dx,
                  " m, but dx must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(dy) && dy > 0, "love_influence: dy = ", dy,
                  " m, but dy must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(x) && std::isfinite(y), "love_influence: (x, y) = (", x, ", ", y,
                  ") m, but both must be finite");
  const double a = 0.5 * dx;
  const double b = 0.5 * dy;
  if (std::hypot(x, y) >= far_field_ratio * std::max(dx, dy)) return gauss_legendre_4x4(x, y, a, b);
  return (corner(x + a, y + b) - corner(x + a, y - b) - corner(x - a, y + b) +
          corner(x - a, y - b)) /
         std::numbers::pi;
}

}  // namespace coatfft
