#pragma once
// Adhesion of a rigid paraboloid on a Winkler foundation with a Dugdale law: the thin-film limit
// of a soft coating bonded to a rigid substrate (docs/contact.md, "Adhesion"). A film of thickness
// t much smaller than the contact and the cohesive zone responds locally, p = k u with
// k = M / t, M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) its constrained (oedometric) modulus. With
// x = delta - r^2 / (2R) the interference of the rigid profile at radius r, each ring carries
//   f(x) = k x            for x >= -s         (in contact; tensile down to -sigma0, s = sigma0 /
//   k),
//        = -sigma0        for -s - h0 < x < -s (lifted off, within the range),
//        = 0              below,
// and the load is P(delta) = 2 pi R * integral_{-inf}^{delta} f(x) dx (since 2 pi r dr = 2 pi R
// dx). Its minimum, at delta = 0, is the pull-off force: P = -2 pi R (w + sigma0^2 / (2 k)), which
// tends to 2 pi w R (the DMT value) as the film thins. Derived here; no transverse coupling, so
// it holds to O(t / a) and with the substrate's compliance neglected.

namespace coatfft {

class Material;

/// The plane-wave stiffness of a thin film bonded to a rigid substrate, k = M / t [Pa/m].
double thin_film_stiffness(const Material& film, double thickness);

/// A rigid paraboloid of radius R [m] on a Winkler foundation of stiffness k [Pa/m] with the
/// Dugdale law of work w [J/m^2] and range h0 [m].
class WinklerDugdale {
 public:
  WinklerDugdale(double radius, double stiffness, double work_of_adhesion, double range);

  /// The load [N] at the approach `delta` [m] (negative when tensile; 0 when out of reach).
  double load_at_approach(double delta) const;
  /// The radius of the contact (the rings at zero gap) [m]; 0 when none.
  double contact_radius(double delta) const;
  /// The outer radius of the cohesive zone [m]; 0 when out of reach.
  double cohesive_radius(double delta) const;
  /// The pull-off force [N] (negative): the load at delta = 0.
  double pull_off_load() const { return load_at_approach(0.0); }
  /// The approach [m] at zero load on the contact's branch.
  double approach_at_zero_load() const;

 private:
  double radius_, stiffness_, work_, range_, strength_;
};

}  // namespace coatfft
