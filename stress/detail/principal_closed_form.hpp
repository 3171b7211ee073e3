#pragma once
// Von Mises' stress and the principal stresses of a symmetric tensor by closed forms (private:
// what von_mises, closed_form_principal_stresses and the summary's screening of every cell share).
// Inline and without branches or calls, so that a loop over the cells vectorises; for tensors
// whose largest component lies in [1e-90, 1e90] Pa, where the cubes below neither overflow nor
// underflow (the public functions scale the others by a power of two first, which changes no
// rounding).
//
// With the mean stress m, the deviator's invariants J2, J3 and rho = 2 sqrt(J2/3), the principal
// stresses are m + rho c for the three roots c of 4 c^3 - 3 c = r, r = 4 J3/rho^3 in [-1, 1]
// (c = cos(acos(r)/3 - 2 pi k/3)). The root of largest modulus, c in [sqrt(3)/2, 1] for |r|, is
// simple: from a cubic fit in |r| (within 6.8e-5), two Newton steps reach it to rounding
// (4.4e-16 over |r| in [0, 1], checked densely while developing this). The other two follow from
// the sum and product of the roots, c = (-c0 -+ sqrt(3 (1 - c0^2)))/2, which near a double root
// (|r| -> 1) lose half the digits, as any closed form does: within 1e-7 of the largest component
// there and 1e-12 on random states (tests/test_stress_operator.cpp; about 2e-8 and 4e-14 in the
// development check).
#include <algorithm>
#include <array>
#include <cmath>

namespace coatfft::detail {

/// sqrt(((xx - yy)^2 + (yy - zz)^2 + (zz - xx)^2)/2 + 3 (yz^2 + xz^2 + xy^2)) [Pa].
inline double von_mises_unscaled(double xx, double yy, double zz, double yz, double xz, double xy) {
  const double a = xx - yy, b = yy - zz, c = zz - xx;
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (yz * yz + xz * xz + xy * xy));
}

/// The largest |component| [Pa].
inline double largest_component(double xx, double yy, double zz, double yz, double xz, double xy) {
  return std::max(
      std::max(std::max(std::abs(xx), std::abs(yy)), std::max(std::abs(zz), std::abs(yz))),
      std::max(std::abs(xz), std::abs(xy)));
}

/// Whether the closed forms here hold for a tensor whose largest |component| is `largest` [Pa]:
/// 0 (a zero tensor), or within [1e-90, 1e90].
inline bool in_closed_form_range(double largest) {
  return largest == 0 || (largest >= 1e-90 && largest <= 1e90);
}

/// s1 >= s2 >= s3 of (xx, yy, zz, yz, xz, xy) [Pa], the largest |component| in [1e-90, 1e90].
inline std::array<double, 3> principal_closed_form(double xx, double yy, double zz, double yz,
                                                   double xz, double xy) {
  constexpr double third = 1.0 / 3.0;
  const double m = (xx + yy + zz) * third;
  const double a = xx - m, b = yy - m, c = zz - m;
  const double j2 = 0.5 * (a * a + b * b + c * c) + yz * yz + xz * xz + xy * xy;
  const double j3 = a * b * c + 2.0 * yz * xz * xy - a * yz * yz - b * xz * xz - c * xy * xy;
  const double rho = 2.0 * std::sqrt(j2 * third);
  // A tensor within about 1e-100 Pa of a hydrostatic one has rho^3 below 1e-300, where its
  // rounding is coarse: r is then anything in [-1, 1], which moves the roots by at most
  // rho/2 (below 1e-6 of 1e-90 Pa).
  const double r = std::min(1.0, std::max(-1.0, 4.0 * j3 / std::max(rho * rho * rho, 1e-300)));
  const double s = std::abs(r);
  double c0 = 0.866093 + s * (0.165215 + s * (-0.0406303 + s * 0.00937443));
  for (int k = 0; k < 2; ++k) c0 -= (4.0 * c0 * c0 * c0 - 3.0 * c0 - s) / (12.0 * c0 * c0 - 3.0);
  const double q = std::sqrt(std::max(0.0, 3.0 * (1.0 - c0 * c0)));
  const double h = 0.5 * (c0 + q);
  const double c1 = r >= 0 ? c0 : h;
  const double c3 = r >= 0 ? -h : -c0;
  const double c2 = -(c1 + c3);
  return {m + rho * c1, m + rho * c2, m + rho * c3};
}

}  // namespace coatfft::detail
