#include "validation/hertz.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/ellint_d.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace coatfft {
namespace {

void check_arguments(const char* who, double r, double p, double a, double e_star) {
  COATFFT_REQUIRE(std::isfinite(r) && r >= 0, who, ": r = ", r,
                  " m, but r must be finite and >= 0");
  COATFFT_REQUIRE(std::isfinite(p), who, ": pressure = ", p, " Pa, but it must be finite");
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, who, ": a = ", a, " m, but a must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(e_star) && e_star > 0, who, ": E* = ", e_star,
                  " Pa, but E* must be finite and > 0");
}

// g(t) = (2t^2 - 1) asin t + t sqrt(1 - t^2), t = a/r, so that (1.7) reads
// u = p0 r^2 g(t) / (2 a E*) = p0 a (g(t)/t^2) / (2 E*). Since g'(t) = 4 t asin t and
// asin t = sum_n c_n t^(2n+1) with c_n = (2n)! / (4^n (n!)^2 (2n+1)),
// g(t)/t^2 = sum_n 4 c_n t^(2n+1) / (2n+3): no cancellation, and no r^2, which overflows (and
// t^3, which underflows) long before u does.
double hertz_outside_series(double t) {
  const double t2 = t * t;
  double binomial = 1.0;  // (2n)! / (4^n (n!)^2)
  double power = t;       // t^(2n+1)
  double sum = 0.0;
  for (int n = 0; n < 200; ++n) {
    const double term = 4.0 * binomial / (2.0 * n + 1.0) * power / (2.0 * n + 3.0);
    sum += term;
    if (term < std::numeric_limits<double>::epsilon() * 1e-2 * sum) break;
    binomial *= (2.0 * n + 1.0) / (2.0 * n + 2.0);
    power *= t2;
  }
  return sum;
}

}  // namespace

double hertz_displacement(double r, double p0, double a, double plane_strain_modulus) {
  check_arguments("hertz_displacement", r, p0, a, plane_strain_modulus);
  const double e_star = plane_strain_modulus;
  if (r <= a) return std::numbers::pi * p0 * (2.0 * a * a - r * r) / (4.0 * a * e_star);
  // (1.7) loses about log10(r^2/a^2) digits to cancellation; beyond r = 2a the series (at most
  // ~30 terms there) is exact to rounding.
  if (r > 2.0 * a) return p0 * a * hertz_outside_series(a / r) / (2.0 * e_star);
  // Near r = a, asin(a/r) has an infinite slope: the rounding of a/r alone would cost 1e-8
  // relative. s = sqrt((r - a)(r + a)) is exact to rounding and asin(a/r) = atan2(a, s).
  const double s = std::sqrt((r - a) * (r + a));
  return p0 / (2.0 * a * e_star) * ((2.0 * a * a - r * r) * std::atan2(a, s) + a * s);
}

Field hertz_displacement_field(const Grid& grid, double p0, double a, double plane_strain_modulus) {
  return hertz_displacement_rows(grid, p0, a, plane_strain_modulus, 0, grid.ny());
}

Field hertz_displacement_rows(const Grid& grid, double p0, double a, double plane_strain_modulus,
                              std::ptrdiff_t y0, std::ptrdiff_t rows) {
  detail::require_rows(grid, y0, rows, "hertz_displacement_rows");
  Field u(grid.nx(), rows);
  for (std::ptrdiff_t j = 0; j < rows; ++j)
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i)
      u(i, j) =
          hertz_displacement(std::hypot(grid.x(i), grid.y(y0 + j)), p0, a, plane_strain_modulus);
  return u;
}

double uniform_disk_displacement(double r, double p, double a, double plane_strain_modulus) {
  check_arguments("uniform_disk_displacement", r, p, a, plane_strain_modulus);
  const double e_star = plane_strain_modulus;
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  using boost::math::ellint_d;
  if (r <= a) return 4.0 * p * a * ellint_2(r / a) / (std::numbers::pi * e_star);
  // (1.9) outside: E(k) - (1 - k^2) K(k) with k = a/r cancels like k^2 as r grows. With
  // D(k) = (K - E)/k^2 it equals k^2 (K(k) - D(k)), a difference of O(1) terms (K -> pi/2,
  // D -> pi/4), so no digits are lost.
  const double k = a / r;
  // r k^2 = a k: k^2 alone underflows at r = 1e300 a, where u itself is still a normal double.
  return 4.0 * p * a * k * (ellint_1(k) - ellint_d(k)) / (std::numbers::pi * e_star);
}

double centre_relative_error(double u_num, double u_exact, double u_exact_centre) {
  COATFFT_REQUIRE(std::isfinite(u_exact_centre) && u_exact_centre != 0.0,
                  "centre_relative_error: u_exact(0) = ", u_exact_centre,
                  " m, but it must be finite and != 0");
  return (u_num - u_exact) / u_exact_centre;
}

}  // namespace coatfft
