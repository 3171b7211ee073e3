#pragma once
// Closed-form stresses of a half-space under a sinusoidal surface load: the plane-strain solutions
// of Johnson (1985), section 2.5, from Airy's stress function. The reference of the periodic
// stresses (stress/stress_operator.hpp with periodic = true).
#include <array>

namespace coatfft {

/// The six stresses (xx, yy, zz, yz, xz, xy) [Pa], tension positive, z into the body, at (x, z)
/// (z >= 0 [m]) in a homogeneous half-space of Poisson's ratio nu under the surface pressure
/// p0 cos(k x) (compression positive) and the traction q0 cos(k x) along +x that the surface
/// receives (k > 0 [rad/m]); uniform along y (plane strain: sigma_yy = nu (sigma_xx + sigma_zz)).
/// Airy's functions: phi = (p0/k^2)(1 + k z) exp(-k z) cos(k x) for the pressure,
/// phi = (q0/k) z exp(-k z) sin(k x) for the traction.
std::array<double, 6> sinusoidal_stress(double k, double p0, double q0, double nu, double x,
                                        double z);

}  // namespace coatfft
