#pragma once
// An isotropic linear-elastic material.

namespace coatfft {

class Material {
 public:
  /// E: Young's modulus [Pa], min_modulus <= E <= max_modulus. nu: Poisson's ratio, finite,
  /// -1 < nu <= max_poisson_ratio.
  /// nu = 0.5 (incompressible) is refused: the coated FRFs divide by (1 - 2 nu) terms through the
  /// Kolosov constant and the project documents nu <= 0.4999 as the supported range.
  Material(double E, double nu);

  /// The largest Poisson's ratio accepted.
  static constexpr double max_poisson_ratio = 0.4999;
  /// The range of E accepted [Pa]: 100 decades on either side of 1 Pa hold every physical
  /// modulus (kPa gels to TPa diamond) in any units, and leave double's other ~200 decades to
  /// loads, lengths and grid sums; E = 1e-308 would make the compliance 2 (1 - nu^2) / E
  /// overflow.
  static constexpr double min_modulus = 1e-100;
  static constexpr double max_modulus = 1e100;

  double youngs_modulus() const { return E_; }  ///< E [Pa]
  double poisson_ratio() const { return nu_; }  ///< nu [-]
  /// Plane-strain (reduced) modulus E* = E / (1 - nu^2) [Pa]; the half-space compliance is 2/(E*
  /// k).
  double plane_strain_modulus() const { return E_ / (1.0 - nu_ * nu_); }
  /// Shear modulus mu = E / (2 (1 + nu)) [Pa].
  double shear_modulus() const { return E_ / (2.0 * (1.0 + nu_)); }
  /// Kolosov constant for plane strain, kappa = 3 - 4 nu [-].
  double kolosov() const { return 3.0 - 4.0 * nu_; }

  bool operator==(const Material&) const = default;

 private:
  double E_;
  double nu_;
};

}  // namespace coatfft
