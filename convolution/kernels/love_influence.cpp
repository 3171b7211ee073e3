#include "convolution/kernels/love_influence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/detail/gauss_legendre.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

// F(X, Y) of docs/theory.md (1.5); each term is defined as 0 where its prefactor is 0 (its limit).
double corner(double X, double Y) {
  double f = 0.0;
  if (X != 0.0) f += X * std::asinh(Y / std::abs(X));
  if (Y != 0.0) f += Y * std::asinh(X / std::abs(Y));
  return f;
}

double love_closed_form(double x, double y, double a, double b) {
  return (corner(x + a, y + b) - corner(x + a, y - b) - corner(x - a, y + b) +
          corner(x - a, y - b)) /
         std::numbers::pi;
}

// Far from the rectangle the 4-corner sum cancels: its terms are O(r) while the result is
// O(dx dy / r), so the closed form loses about eps r^2 / (dx dy) (2e-12 at r = 32 max(dx, dy) for
// a 0.3 x 1 cell). There 1/R is analytic over the rectangle and an n-point Gauss-Legendre product
// rule converges like rho^(-2n), rho ~ 4 r / d, d = max(dx, dy) (Bernstein ellipse through the
// singularity). Measured relative errors (24-point long-double reference, square and 0.3 x 1
// cells, along the axes and the diagonal) fit c_n (d/r)^(2n) with c_2 = 8e-3, c_3 = 2.4e-4,
// c_4 = 2.9e-5, c_5 = 1e-6: the switches below keep every coefficient within ~1e-16 relative of
// the exact value (exact to rounding), using as few square roots as that allows:
//   r/d in [8, 12): n = 6 (2e-18);  [12, 32): n = 5 (<= 1.6e-17);  [32, 128): n = 4 (<= 2.6e-17);
//   [128, 4096): n = 3 (<= 5.6e-17);  >= 4096: n = 2 (<= 3e-17).
// At 1024^2 almost every cell is in the 3 x 3 range: 9 square roots per coefficient instead of 36.
// The switch to quadrature at 8 d bounds the closed form's cancellation by
// ~64 eps max(dx, dy) / min(dx, dy).
constexpr std::array<double, 5> switch_ratio = {8.0, 12.0, 32.0, 128.0, 4096.0};  // n = 6..2

// out[i] = N x N Gauss-Legendre value of love_influence(x0 + i step, y) for i in [first, end).
// The node sums are unrolled inside the loop over i, which carries no dependence and vectorises
// (with -fno-math-errno, set for this file); a single point (first = 0, end = 1, step = 0) goes
// through the same arithmetic, so love_kernel and love_influence agree bit for bit.
template <int N>
void gauss_legendre_run(double x0, double step, int first, int end, double y, double a, double b,
                        double* out) {
  // Local copies of the weights: stores through `out` cannot alias them, so they stay in
  // registers across the loop.
  const std::array<double, N> t = detail::gauss_legendre<N>().nodes;
  const std::array<double, N> w = detail::gauss_legendre<N>().weights;
  std::array<double, N> ey2{};
  std::array<double, N> ax{};
  for (std::size_t q = 0; q < N; ++q) {
    const double ey = y - b * t[q];
    ey2[q] = ey * ey;
    ax[q] = a * t[q];
  }
  const double scale = a * b / std::numbers::pi;
  // An int counter: SSE2 converts int32 to double in vectors, not int64.
  for (int i = first; i < end; ++i) {
    const double x = x0 + static_cast<double>(i) * step;
    double sum = 0.0;
    for (std::size_t p = 0; p < N; ++p) {
      const double ex = x - ax[p];
      const double ex2 = ex * ex;
      double row = 0.0;
      for (std::size_t q = 0; q < N; ++q) row += w[q] / std::sqrt(ex2 + ey2[q]);
      sum += w[p] * row;
    }
    out[i] = scale * sum;
  }
}

// The rule order for squared distance r2 from the cell centre: 0 (closed form) or 6..2.
int rule_order(double r2, double d) {
  int n = 0;
  for (std::size_t s = 0; s < switch_ratio.size(); ++s) {
    const double limit = switch_ratio[s] * d;
    if (r2 >= limit * limit) n = 6 - static_cast<int>(s);
  }
  return n;
}

void run_with_order(int n, double x0, double step, int first, int end, double y, double a, double b,
                    double* out) {
  switch (n) {
    case 6:
      gauss_legendre_run<6>(x0, step, first, end, y, a, b, out);
      break;
    case 5:
      gauss_legendre_run<5>(x0, step, first, end, y, a, b, out);
      break;
    case 4:
      gauss_legendre_run<4>(x0, step, first, end, y, a, b, out);
      break;
    case 3:
      gauss_legendre_run<3>(x0, step, first, end, y, a, b, out);
      break;
    default:
      gauss_legendre_run<2>(x0, step, first, end, y, a, b, out);
      break;
  }
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
  const int n = rule_order(x * x + y * y, std::max(dx, dy));
  if (n == 0) return love_closed_form(x, y, a, b);
  double v = 0.0;
  run_with_order(n, x, 0.0, 0, 1, y, a, b, &v);
  return v;
}

namespace detail {

void love_influence_row(double y, double dx, double dy, std::ptrdiff_t count, double* out) {
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0,
                  "love_influence_row: cell (", dx, ", ", dy, ") m must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(y), "love_influence_row: y = ", y, " m, but it must be finite");
  COATFFT_REQUIRE(count >= 0 && count <= std::numeric_limits<int>::max(),
                  "love_influence_row: count = ", count, ", but it must be in [0, INT_MAX]");
  const double a = 0.5 * dx;
  const double b = 0.5 * dy;
  const double d = std::max(dx, dy);
  // The order falls with i (r grows along the row): runs of equal order, each one vectorised.
  std::ptrdiff_t i = 0;
  while (i < count) {
    const double x = static_cast<double>(i) * dx;
    const int n = rule_order(x * x + y * y, d);
    std::ptrdiff_t end = i + 1;
    while (end < count) {
      const double xe = static_cast<double>(end) * dx;
      if (rule_order(xe * xe + y * y, d) != n) break;
      ++end;
    }
    if (n == 0) {
      for (std::ptrdiff_t k = i; k < end; ++k)
        out[k] = love_closed_form(static_cast<double>(k) * dx, y, a, b);
    } else {
      // x0 = 0, step dx: x = 0 + k dx is the x of love_influence(k dx, y, ...) exactly.
      run_with_order(n, 0.0, dx, static_cast<int>(i), static_cast<int>(end), y, a, b, out);
    }
    i = end;
  }
}

}  // namespace detail
}  // namespace coatfft
