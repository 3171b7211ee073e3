#include "loads/axisymmetric_load.hpp"

#include <gsl/gsl_sf_bessel.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace coatfft {

// docs/theory.md §1.4: Phi_H = j1(s)/s; §1.5: Phi_U = J1(s)/s.
double axisymmetric_load_shape(AxisymmetricLoad load, double s) {
  if (load == AxisymmetricLoad::hertz) {
    if (s < 1e-4) return 1.0 / 3.0 - s * s / 30.0;  // next term s^4/840 < 1e-19
    return gsl_sf_bessel_j1(s) / s;
  }
  if (s < 1e-4) return 0.5 - s * s / 16.0;  // next term s^4/384 < 1e-18
  return gsl_sf_bessel_J1(s) / s;
}

double axisymmetric_load_transform(AxisymmetricLoad load, double amplitude, double a, double k) {
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "axisymmetric_load_transform: a = ", a,
                  " m, but a must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(k) && k >= 0, "axisymmetric_load_transform: k = ", k,
                  " rad/m, but k must be finite and >= 0");
  return 2.0 * std::numbers::pi * amplitude * a * a * axisymmetric_load_shape(load, k * a);
}

}  // namespace coatfft
