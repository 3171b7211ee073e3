#pragma once
// Partial slip of a Hertz contact under a tangential load (Cattaneo 1938; Mindlin 1949; Johnson,
// Contact Mechanics (1985), section 7.2) and its unloading and reloading (Mindlin & Deresiewicz
// 1953, Masing's rule): the references of frictional contacts, valid where the tangential
// tractions leave the pressure as it is (identical bodies, or an incompressible one). The closed
// forms are docs/theory.md 6.5's.
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "hertz_contact.hpp"

namespace coatfft {

struct CattaneoMindlin {
  HertzSphere hertz;  ///< the normal contact: load P [N], radius a [m], peak pressure p0 [Pa]
  double friction;    ///< mu > 0
  /// (2 - nu)/G [1/Pa], summed over the two bodies when both are elastic (Johnson eq. 7.43).
  double compliance;

  /// Radius of the stick zone c = a (1 - Q/(mu P))^(1/3) [m] under 0 <= Q < mu P [N].
  double stick_radius(double tangential_load) const;
  /// The traction along the load, q(r) = mu p0 sqrt(1 - r^2/a^2) - (c/a) mu p0 sqrt(1 - r^2/c^2)
  /// (the second term inside the stick zone only) [Pa], at r [m] >= 0 under Q [N].
  double traction(double r, double tangential_load) const;
  /// The tangential shift of the indenter against the body's far field under Q loaded
  /// monotonically from 0: delta = 3 mu P compliance/(16 a) [1 - (1 - Q/(mu P))^(2/3)] [m].
  double shift(double tangential_load) const;
  /// The shift on unloading from Q* [N] down to Q (Masing's rule): delta(Q*) - 2 delta((Q* - Q)/2)
  /// [m]; -Q* <= Q <= Q*. Reloading from -Q* is its mirror image.
  double unloading_shift(double reversal_load, double tangential_load) const;
  /// The energy a full cycle between -Q* and +Q* dissipates, the area of its loop (Johnson eq.
  /// 7.59): 9 mu^2 P^2 compliance/(10 a) [1 - (1 - x)^(5/3) - (5 x/6)(1 + (1 - x)^(2/3))] [J],
  /// x = Q*/(mu P) < 1.
  double loop_energy(double reversal_load) const;
};

/// The root-mean-square difference between a traction field q_x [Pa] on `grid` (cell values,
/// the sphere on the grid's centre) and `reference`'s traction under Q [N], over the cells whose
/// centre lies inside the Hertz contact, divided by mu p0: the error measure of the partial-slip
/// tables and tests.
double rms_traction_error(const Grid& grid, const Field& qx, const CattaneoMindlin& reference,
                          double tangential_load);

/// The partial slip of a rigid sphere of radius R [m] pressed with P [N] on a half-space of
/// `material` (E*, and (2 - nu)/G), friction mu > 0. InvalidArgument for a value out of range.
CattaneoMindlin cattaneo_mindlin(double load, double radius, const Material& material,
                                 double friction);

}  // namespace coatfft
