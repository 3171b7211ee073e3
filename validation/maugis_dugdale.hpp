#pragma once
// Adhesion of a rigid sphere on an elastic half-space with a Dugdale cohesive zone (Maugis 1992;
// Johnson & Greenwood 1997): the reference of the adhesive contact solver. A tensile stress
// sigma0 acts where the gap lies between 0 and h0, none beyond; the work of adhesion is
// w = sigma0 h0. In Maugis' variables, K = 4 E*/3, m = c/a (c: the cohesive zone's edge),
//   lambda = 2 sigma0 (R / (pi w K^2))^(1/3),   A = a (K / (pi w R^2))^(1/3),
//   Pbar = P / (pi w R),   D = delta (K^2 / (pi^2 w^2 R))^(1/3),
// and for each m > 1 (x = sqrt(m^2 - 1)):
//   (lambda A^2/2)[x + (m^2 - 2) atan x] + (4 lambda^2 A/3)[x atan x - m + 1] = 1   (A from m)
//   Pbar = A^3 - lambda A^2 [x + m^2 atan x],   D = A^2 - (4/3) A lambda x.
// Pull-off, the most tensile load of the curve, runs from 2 pi w R (DMT, lambda -> 0) to
// 1.5 pi w R (JKR, lambda -> infinity).
#include <vector>

namespace coatfft {

/// One point of the curve, in physical units.
struct MaugisDugdalePoint {
  double m;                ///< c / a [-]
  double contact_radius;   ///< a [m]
  double cohesive_radius;  ///< c [m]
  double load;             ///< P [N], negative when tensile
  double approach;         ///< delta [m], from first touch without adhesion
};

/// A sphere of radius R [m] on a half-space of plane-strain modulus E* [Pa] with the Dugdale law
/// of work w [J/m^2] and range h0 [m].
class MaugisDugdale {
 public:
  MaugisDugdale(double radius, double plane_strain_modulus, double work_of_adhesion, double range);

  /// Maugis' parameter lambda [-].
  double lambda() const { return lambda_; }
  /// The point of the curve at m > 1.
  MaugisDugdalePoint at(double m) const;
  /// The curve at m from just above 1 to `m_max`, `count` points spaced geometrically in m - 1,
  /// in order of growing m (from large contact to the edge of the cohesive zone's reach).
  std::vector<MaugisDugdalePoint> curve(double m_max, int count) const;
  /// The most tensile load of the curve [N] (negative): the pull-off force, by golden-section
  /// search on m over the curve's minimum.
  double pull_off_load() const;
  /// The load [N] at the approach `delta` [m] on the branch of the largest contact (the one an
  /// approach-controlled contact follows from a large approach down, until it jumps off), or
  /// NaN below the branch's smallest approach.
  double load_at_approach(double delta) const;

 private:
  double radius_, modulus_, work_, range_;
  double k_, lambda_;
  double a_scale_, p_scale_, d_scale_;  // a = A a_scale, P = Pbar p_scale, delta = D d_scale
};

}  // namespace coatfft
