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
// O(dx dy / r), so the closed form loses about eps r^2 / (dx dy) (2e-12 at r = 32 max(dx, dy) for
// a 0.3 x 1 cell). There 1/R is analytic over the rectangle, and an n-point Gauss-Legendre product
// rule converges like rho^(-2n) with rho ~ 4 r / max(dx, dy) >= 32 beyond the switch: with n = 6,
// ~1e-18, i.e. exact to rounding, for 36 square roots instead of 8 asinh. The switch at
// 8 max(dx, dy) bounds the closed form's cancellation by ~64 eps max(dx, dy) / min(dx, dy).
constexpr double far_field_ratio = 8.0;

double gauss_legendre_6x6(double x, double y, double a, double b) {
  // Nodes and weights of the 6-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun 25.4.30).
  constexpr std::array<double, 6> t = {-0.932469514203152028, -0.661209386466264514,
                                       -0.238619186083196909, 0.238619186083196909,
                                       0.661209386466264514,  0.932469514203152028};
  constexpr std::array<double, 6> w = {0.171324492379170345, 0.360761573048138608,
                                       0.467913934572691047, 0.467913934572691047,
                                       0.360761573048138608, 0.171324492379170345};
  double sum = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double ex = x - a * t[i];
    double row = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j) {
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
  if (std::hypot(x, y) >= far_field_ratio * std::max(dx, dy)) return gauss_legendre_6x6(x, y, a, b);
  return (corner(x + a, y + b) - corner(x + a, y - b) - corner(x - a, y + b) +
          corner(x - a, y - b)) /
         std::numbers::pi;
}

}  // namespace coatfft
