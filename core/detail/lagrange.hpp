#pragma once
// Six-point (quintic) Lagrange interpolation on uniform nodes (private: not installed), the one
// used by the library's uniform tables (the split kernel's Hankel and alias-fold tables). Error
// about 0.005 (h w)^6 of the function's scale for a function band-limited to w, h the node step.
#include <array>

namespace coatfft::detail {

/// The weights of the nodes -2, -1, 0, 1, 2, 3 (in steps) for the value at t, usually in [0, 1)
/// (the centred interval; any t extrapolates the same quintic). Product form: prefix and suffix
/// products of the distances t - j and the constants 1/prod(node differences) = 1/120, 1/24,
/// 1/12: about 20 multiplications and no division, against 30 divisions for the generic loop.
inline std::array<double, 6> lagrange6_weights(double t) {
  const double m0 = t + 2.0, m1 = t + 1.0, m2 = t, m3 = t - 1.0, m4 = t - 2.0, m5 = t - 3.0;
  const double p01 = m0 * m1, p012 = p01 * m2, p0123 = p012 * m3, p01234 = p0123 * m4;
  const double s45 = m4 * m5, s345 = m3 * s45, s2345 = m2 * s345, s12345 = m1 * s2345;
  return {-s12345 * (1.0 / 120.0),   m0 * s2345 * (1.0 / 24.0),  -p01 * s345 * (1.0 / 12.0),
          p012 * s45 * (1.0 / 12.0), -p0123 * m5 * (1.0 / 24.0), p01234 * (1.0 / 120.0)};
}

/// The quintic through f[0..5], the values at the nodes -2, -1, 0, 1, 2, 3, evaluated at t.
inline double lagrange6(const double* f, double t) {
  const std::array<double, 6> w = lagrange6_weights(t);
  return (w[0] * f[0] + w[5] * f[5]) + (w[1] * f[1] + w[4] * f[4]) + (w[2] * f[2] + w[3] * f[3]);
}

}  // namespace coatfft::detail
