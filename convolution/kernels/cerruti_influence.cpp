#include "convolution/kernels/cerruti_influence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/detail/gauss_legendre.hpp"
#include "core/error.hpp"
#include "materials/material.hpp"

namespace coatfft {
namespace {

// All forms below are for mu = 1 Pa and a field point in the first quadrant x, y >= 0; the
// caller restores the signs (xx even, yx odd-odd, zx odd in x) and divides by mu.

// (1.5b): the corner function Y asinh(X/|Y|) + (1 - nu) X asinh(Y/|X|), each term 0 where its
// prefactor is 0 (its limit), as Love's F of (1.5).
double corner_xx(double X, double Y, double nu) {
  double f = 0.0;
  if (Y != 0.0) f += Y * std::asinh(X / std::abs(Y));
  if (X != 0.0) f += (1.0 - nu) * X * std::asinh(Y / std::abs(X));
  return f;
}

// (1.5c): the corner sum of -R, R = |(X, Y)|, as a product of sums of distances (no
// cancellation anywhere, any distance): 16 a b x y [1/T(x+a) + 1/T(x-a)] / (S(y+b) S(y-b)).
double corner_sum_yx(double x, double y, double a, double b) {
  const double t_plus = std::hypot(x + a, y + b) + std::hypot(x + a, y - b);
  const double t_minus = std::hypot(x - a, y + b) + std::hypot(x - a, y - b);
  const double s_plus = std::hypot(x + a, y + b) + std::hypot(x - a, y + b);
  const double s_minus = std::hypot(x + a, y - b) + std::hypot(x - a, y - b);
  return (4.0 * a * x / s_plus) * (4.0 * b * y / s_minus) * (1.0 / t_plus + 1.0 / t_minus);
}

// (1.5d), x >= 0: Y ln R paired along x, L(Y) = Y/2 ln(((x+a)^2 + Y^2)/((x-a)^2 + Y^2)); the
// ratio is >= 1 for x >= 0, so log1p of a non-negative argument: accurate to rounding, and 0 for
// Y = 0 (its limit, also at the corner x = a where the log diverges).
double pair_log(double x, double Y, double a) {
  if (Y == 0.0) return 0.0;
  const double xm = x - a;
  return 0.5 * Y * std::log1p(4.0 * a * x / (xm * xm + Y * Y));
}

// (1.5d), x >= 0: X atan(Y/X) paired along y is |X| theta(X), theta(X) in [0, pi] the angle that
// the segment X = const, |y'| <= b subtends at the field point: theta = arg(z(X)),
// z(X) = (X + i(y+b))(X - i(y-b)) = X^2 + P + 2 i b X, P = (y+b)(y-b). With X1 = x + a and
// X2 = |x - a|, the pair X1 theta(X1) - X2 theta(X2) is written as
//   (X1 + X2)/2 (theta1 - theta2) + (X1 - X2)/2 (theta1 + theta2),  X1 - X2 = 2 min(x, a),
// with theta1 - theta2 = arg(z1 conj(z2)), Im(z1 conj(z2)) = 2b (X1 - X2)(P - X1 X2): both terms
// proportional to min(x, a), so nothing cancels as x -> 0 (zx is odd in x). On the edge x = a,
// X2 = 0 and the pair is X1 theta1 alone (at the corners z2 = 0 and arg(z2) is undefined).
double pair_angles(double x, double y, double a, double b) {
  const double x1 = x + a;
  const double x2 = std::abs(x - a);
  if (x2 == 0.0) return x1 * std::atan2(2.0 * b * x1, x1 * x1 + (y + b) * (y - b));
  const double lo = std::min(x, a);
  const double hi = std::max(x, a);
  const double p = (y + b) * (y - b);
  const double theta1 = std::atan2(2.0 * b * x1, x1 * x1 + p);
  const double theta2 = std::atan2(2.0 * b * x2, x2 * x2 + p);
  const double difference = std::atan2(4.0 * b * lo * (p - x1 * x2),
                                       (x1 * x1 + p) * (x2 * x2 + p) + 4.0 * b * b * x1 * x2);
  return hi * difference + lo * (theta1 + theta2);
}

struct CerrutiPair {
  double xx, zx;
};

// Closed forms of xx and zx (mu = 1 Pa), x, y >= 0, lengths in units of the larger side (so that
// the fourth powers of pair_angles stay far from overflow).
CerrutiPair cerruti_closed_form(double x, double y, double a, double b, double nu) {
  const double xx = (corner_xx(x + a, y + b, nu) - corner_xx(x + a, y - b, nu) -
                     corner_xx(x - a, y + b, nu) + corner_xx(x - a, y - b, nu)) /
                    (2.0 * std::numbers::pi);
  const double sum = pair_log(x, y + b, a) - pair_log(x, y - b, a) + pair_angles(x, y, a, b);
  return {xx, (1.0 - 2.0 * nu) / (4.0 * std::numbers::pi) * sum};
}

// Far from the cell the corner sums of xx and zx cancel (their terms are O(r) and O(d), the
// results O(d^2/r)), and there the kernels (1 - nu)/R + nu X^2/R^3 and X/R^2 are analytic over the
// cell: an N x N Gauss-Legendre product rule converges like (4 r/d)^(-2N) as for Love's 1/R.
// The nodes are symmetric, t and -t: the zx terms of a pair are summed as
//   (x - a t)/R1^2 + (x + a t)/R2^2 = 2 x (x^2 - a^2 t^2 + Y^2)/(R1^2 R2^2),
// proportional to x, so that zx keeps its relative accuracy near the axis x = 0 (no cancellation
// of x - a t against x + a t) and vanishes there exactly.
template <int N>
CerrutiPair gauss_legendre_rule(double x, double y, double a, double b, double nu) {
  const auto& rule = detail::gauss_legendre<N>();
  double sxx = 0.0;
  double szx = 0.0;
  for (std::size_t p = 0; p < N / 2; ++p) {
    const double at = a * rule.nodes[N - 1 - p];
    const double e1 = x - at;
    const double e2 = x + at;
    const double e12 = e1 * e1;
    const double e22 = e2 * e2;
    const double core = x * x - at * at;
    double rxx = 0.0;
    double rzx = 0.0;
    for (std::size_t q = 0; q < N; ++q) {
      const double ey = y - b * rule.nodes[q];
      const double ey2 = ey * ey;
      const double inv1 = 1.0 / (e12 + ey2);
      const double inv2 = 1.0 / (e22 + ey2);
      rxx += rule.weights[q] * (std::sqrt(inv1) * (1.0 - nu * ey2 * inv1) +
                                std::sqrt(inv2) * (1.0 - nu * ey2 * inv2));
      rzx += rule.weights[q] * (core + ey2) * inv1 * inv2;
    }
    sxx += rule.weights[N - 1 - p] * rxx;
    szx += rule.weights[N - 1 - p] * 2.0 * rzx;
  }
  if constexpr (N % 2 == 1) {  // the node t = 0
    const double x2 = x * x;
    double rxx = 0.0;
    double rzx = 0.0;
    for (std::size_t q = 0; q < N; ++q) {
      const double ey = y - b * rule.nodes[q];
      const double ey2 = ey * ey;
      const double inv = 1.0 / (x2 + ey2);
      rxx += rule.weights[q] * std::sqrt(inv) * (1.0 - nu * ey2 * inv);
      rzx += rule.weights[q] * inv;
    }
    sxx += rule.weights[N / 2] * rxx;
    szx += rule.weights[N / 2] * rzx;
  }
  const double area = a * b;
  return {area * sxx / (2.0 * std::numbers::pi),
          area * x * (1.0 - 2.0 * nu) / (4.0 * std::numbers::pi) * szx};
}

// The rule order for squared distance r2 from the cell centre in units of max(dx, dy): 0 (closed
// form) or 6..2. Measured (a 30 x 30 long-double rule as reference, nu = 0, 0.3, 0.49, cells
// 1 x 1, 1 x 0.3, 1 x 0.1, 1 x 0.01 and transposed, 65 directions, just past each switch): every
// rule is within 6.3e-16 relative of the exact xx and zx, the rounding of the double sums, while
// one order less at the same switch gives up to 1.5e-14 (n = 5 at 8), 4e-15 (n = 4 at 24) and
// 3.4e-15 (n = 2 at 2048). The closed forms lose, just inside 8: xx ~64 eps max(dx, dy)/min(dx,
// dy) (Love's cancellation, 1.6e-13 for a 1 x 0.1 cell), zx ~8 eps max(dx, dy)/min(dx, dy)
// (1.5e-14).
constexpr std::array<double, 5> switch_ratio = {8.0, 12.0, 48.0, 256.0, 4096.0};  // n = 6..2

int rule_order(double r2) {
  int n = 0;
  for (std::size_t s = 0; s < switch_ratio.size(); ++s)
    if (r2 >= switch_ratio[s] * switch_ratio[s]) n = 6 - static_cast<int>(s);
  return n;
}

CerrutiPair far_field(int n, double x, double y, double a, double b, double nu) {
  switch (n) {
    case 6:
      return gauss_legendre_rule<6>(x, y, a, b, nu);
    case 5:
      return gauss_legendre_rule<5>(x, y, a, b, nu);
    case 4:
      return gauss_legendre_rule<4>(x, y, a, b, nu);
    case 3:
      return gauss_legendre_rule<3>(x, y, a, b, nu);
    default:
      return gauss_legendre_rule<2>(x, y, a, b, nu);
  }
}

}  // namespace

CerrutiCoefficients cerruti_influence(double x, double y, double dx, double dy,
                                      const Material& material) {
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0, "cerruti_influence: dx = ", dx,
                  " m, but dx must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(dy) && dy > 0, "cerruti_influence: dy = ", dy,
                  " m, but dy must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(x) && std::isfinite(y), "cerruti_influence: (x, y) = (", x, ", ", y,
                  ") m, but both must be finite");
  const double nu = material.poisson_ratio();
  // Lengths in units of the larger side d; every form is evaluated in the first quadrant and the
  // symmetries give the signs, so that they hold bit for bit.
  const double d = std::max(dx, dy);
  const double xs = std::abs(x) / d;
  const double ys = std::abs(y) / d;
  const double a = 0.5 * dx / d;
  const double b = 0.5 * dy / d;
  const int n = rule_order(xs * xs + ys * ys);
  const CerrutiPair p =
      n == 0 ? cerruti_closed_form(xs, ys, a, b, nu) : far_field(n, xs, ys, a, b, nu);
  const double yx = nu / (2.0 * std::numbers::pi) * corner_sum_yx(xs, ys, a, b);
  const double scale = d / material.shear_modulus();
  const double sign_x = std::signbit(x) ? -1.0 : 1.0;
  const double sign_y = std::signbit(y) ? -1.0 : 1.0;
  return {scale * p.xx, sign_x * sign_y * scale * yx, sign_x * scale * p.zx};
}

}  // namespace coatfft
