#include "validation/sinusoidal_stress.hpp"

#include <cmath>

namespace coatfft {

std::array<double, 6> sinusoidal_stress(double k, double p0, double q0, double nu, double x,
                                        double z) {
  const double kz = k * z, e = std::exp(-kz), c = std::cos(k * x), s = std::sin(k * x);
  // sigma_xx = phi_zz, sigma_zz = phi_xx, sigma_xz = -phi_xz; at z = 0: sigma_zz = -p0 cos(k x),
  // sigma_xz = -q0 cos(k x).
  const double sxx = -e * (p0 * (1 - kz) * c + q0 * (2 - kz) * s);
  const double szz = -e * (p0 * (1 + kz) * c + q0 * kz * s);
  const double sxz = -e * (p0 * kz * s + q0 * (1 - kz) * c);
  return {sxx, nu * (sxx + szz), szz, 0.0, sxz, 0.0};
}

}  // namespace coatfft
