#pragma once
// Cancellation-free hyperbolic combinations that vanish like x^3 at x = 0. The coated and layered
// FRFs need them because their small-kh behaviour (thin layers, squeeze films,
// docs/theory.md §2.6(c)) lives in exactly these differences; forming them by subtraction would
// lose ~2 log10(1/x) digits.
#include <cmath>

namespace coatfft::detail {

/// The smallest k h_j the layered FRFs use. Frictionless interfaces make the tangential compliance
/// grow like 1/(kh)^2 as kh -> 0 (the layer slides rigidly, docs/theory.md §2.3); clamping kh_j
/// at 1e-60 keeps it finite (< 1e125) in every product, and a k h_j that underflows to 0 cannot
/// make a system singular, while H_zz, which depends on kh_j through O(kh_j) terms, changes by
/// ~1e-60.
inline constexpr double min_kh = 1e-60;

/// sinh(x) - x for x >= 0, to a few ulps: Taylor series (Horner, 10 terms) below 1, direct above.
inline double sinh_minus_x(double x) {
  if (x >= 1.0) return std::sinh(x) - x;  // the subtraction loses < 1 bit: sinh(1) - 1 > 0.17
  const double x2 = x * x;
  // sum_{n>=1} x^(2n+1)/(2n+1)! = x^3/6 * (1 + x^2/(4*5) (1 + x^2/(6*7) (...))); the n = 11 term
  // is < 1/23! * 6 ~ 2e-22 relative at x = 1.
  double s = 1.0;
  for (int n = 10; n >= 2; --n) s = 1.0 + s * x2 / (2.0 * n * (2.0 * n + 1.0));
  return x * x2 / 6.0 * s;
}

/// x cosh(x) - sinh(x) for x >= 0: Taylor series sum_{n>=1} 2n x^(2n+1)/(2n+1)! below 1.
inline double x_cosh_minus_sinh(double x) {
  if (x >= 1.0) return x * std::cosh(x) - std::sinh(x);  // >= 0.37 of x cosh x: no real loss
  const double x2 = x * x;
  // Consecutive terms have the ratio x^2/(2n (2n + 3)).
  double s = 1.0;
  for (int n = 10; n >= 1; --n) s = 1.0 + s * x2 / (2.0 * n * (2.0 * n + 3.0));
  return x * x2 / 3.0 * s;
}

}  // namespace coatfft::detail
