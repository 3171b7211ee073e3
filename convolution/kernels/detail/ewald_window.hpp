#pragma once
// The window of the Ewald-type splits (Ewald 1921) of frf-split (docs/split_kernel.md) and of the
// stress kernels (docs/stress.md): w = exp(-s) (1 + s + s^2/2), s = (sigma k)^2. A spectrum R is
// split as R = R w + R (1 - w). 1 - w = exp(-s) sum_{j>=3} s^j/j! = O(k^6): the short-range part
// then has the far field (sigma^6/6) (-lap)^3 of R's tail, so its periodic images (>= 32 sigma
// away) are negligible (a plain Gaussian, 1 - w = O(k^2), leaves 9 (sigma/r)^2 of an r^-3 tail:
// 1e-2 at 32 sigma). sigma = 0 puts all of R in the short-range part, sigma = inf all of it in
// the long-range part. (Private header: not installed.)
#include <cmath>

namespace coatfft::detail {

inline double ewald_window(double sigma, double k) {
  if (sigma == 0.0) return 0.0;
  if (std::isinf(sigma)) return 1.0;
  const double s = (sigma * k) * (sigma * k);
  return std::exp(-s) * (1.0 + s * (1.0 + 0.5 * s));
}

/// 1 - ewald_window(sigma, k), without the cancellation at small s.
inline double ewald_window_complement(double sigma, double k) {
  if (sigma == 0.0) return 1.0;
  if (std::isinf(sigma)) return 0.0;
  const double s = (sigma * k) * (sigma * k);
  if (s >= 1.0) return 1.0 - std::exp(-s) * (1.0 + s * (1.0 + 0.5 * s));
  // exp(-s) s^3/6 (1 + s/4 + s^2/20 + ...), 12 terms: converged to rounding for s < 1.
  double term = 1.0;
  double sum = 1.0;
  for (int j = 4; j < 16; ++j) {
    term *= s / j;
    sum += term;
  }
  return std::exp(-s) * s * s * s / 6.0 * sum;
}

}  // namespace coatfft::detail
