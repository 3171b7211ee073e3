#pragma once
// Closed-form contact solutions used as references: Hertz's sphere (paraboloid) and the rigid flat
// circular punch (Boussinesq 1885; Sneddon 1965), for a rigid indenter on an elastic half-space of
// plane-strain modulus E* (or two elastic bodies with the composite modulus). Johnson, Contact
// Mechanics (1985): section 3.4 (the punch pressure p0 (1 - r^2/a^2)^(-1/2)) and section 4.2.
#include "../materials/material.hpp"

namespace coatfft {

/// Composite (effective) modulus E* [Pa] of two elastic bodies:
/// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson section 4.2).
double composite_modulus(const Material& body1, const Material& body2);

/// Hertz contact of a sphere of radius R on a half-space (Johnson section 4.2.1).
struct HertzSphere {
  double load;            ///< W [N]
  double contact_radius;  ///< a = (3 W R / (4 E*))^(1/3) [m]
  double max_pressure;    ///< p0 = 3 W / (2 pi a^2) [Pa]
  double approach;        ///< delta = a^2 / R [m]

  /// p(r) = p0 sqrt(1 - r^2/a^2) for r < a, else 0 [Pa]; r [m].
  double pressure(double r) const;
};

/// Hertz sphere under load W [N] > 0, radius R [m] > 0, plane-strain modulus E* [Pa] > 0.
HertzSphere hertz_sphere_for_load(double load, double radius, double plane_strain_modulus);
/// Hertz sphere at approach delta [m] > 0: a = sqrt(R delta), W = (4/3) E* sqrt(R) delta^(3/2).
HertzSphere hertz_sphere_for_approach(double approach, double radius, double plane_strain_modulus);

/// Total load W = 2 a E* delta [N] of a rigid flat circular punch of radius a [m] pressed to
/// approach delta [m] (all arguments finite and > 0).
double flat_punch_load(double radius, double approach, double plane_strain_modulus);
/// Pressure p(r) = W / (2 pi a sqrt(a^2 - r^2)) [Pa] under a rigid flat punch, r < a [m].
double flat_punch_pressure(double r, double radius, double load);

}  // namespace coatfft
