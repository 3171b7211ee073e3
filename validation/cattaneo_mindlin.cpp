#include "validation/cattaneo_mindlin.hpp"

#include <cmath>

#include "core/error.hpp"

namespace coatfft {

namespace {

// Q/(mu P), checked to lie in [0, 1).
double load_ratio(const CattaneoMindlin& c, double tangential_load, const char* who) {
  const double x = tangential_load / (c.friction * c.hertz.load);
  COATFFT_REQUIRE(std::isfinite(x) && x >= 0.0 && x < 1.0, who, ": tangential load ",
                  tangential_load, " N must be in [0, mu P) = [0, ", c.friction * c.hertz.load,
                  ") N");
  return x;
}

}  // namespace

double CattaneoMindlin::stick_radius(double tangential_load) const {
  return hertz.contact_radius * std::cbrt(1.0 - load_ratio(*this, tangential_load, "stick_radius"));
}

double CattaneoMindlin::traction(double r, double tangential_load) const {
  const double c = stick_radius(tangential_load), a = hertz.contact_radius;
  const double slip = friction * hertz.pressure(r);
  if (r >= c) return slip;
  return slip - (c / a) * friction * hertz.max_pressure * std::sqrt(1.0 - (r / c) * (r / c));
}

double CattaneoMindlin::shift(double tangential_load) const {
  const double x = load_ratio(*this, tangential_load, "shift");
  return 3.0 * friction * hertz.load * compliance / (16.0 * hertz.contact_radius) *
         (1.0 - std::pow(1.0 - x, 2.0 / 3.0));
}

double CattaneoMindlin::unloading_shift(double reversal_load, double tangential_load) const {
  COATFFT_REQUIRE(std::abs(tangential_load) <= reversal_load,
                  "unloading_shift: Q = ", tangential_load,
                  " N must be in [-Q*, Q*], Q* = ", reversal_load, " N");
  return shift(reversal_load) - 2.0 * shift(0.5 * (reversal_load - tangential_load));
}

double CattaneoMindlin::loop_energy(double reversal_load) const {
  const double x = load_ratio(*this, reversal_load, "loop_energy");
  const double mu_p = friction * hertz.load;
  return 9.0 * mu_p * mu_p * compliance / (10.0 * hertz.contact_radius) *
         (1.0 - std::pow(1.0 - x, 5.0 / 3.0) -
          (5.0 * x / 6.0) * (1.0 + std::pow(1.0 - x, 2.0 / 3.0)));
}

CattaneoMindlin cattaneo_mindlin(double load, double radius, const Material& material,
                                 double friction) {
  COATFFT_REQUIRE(std::isfinite(friction) && friction > 0.0,
                  "cattaneo_mindlin: friction = ", friction, " must be finite and > 0");
  const double nu = material.poisson_ratio();
  return {hertz_sphere_for_load(load, radius, material.plane_strain_modulus()), friction,
          (2.0 - nu) / material.shear_modulus()};
}

double rms_traction_error(const Grid& grid, const Field& qx, const CattaneoMindlin& reference,
                          double tangential_load) {
  COATFFT_REQUIRE(qx.rows() == grid.nx() && qx.cols() == grid.ny(),
                  "rms_traction_error: the traction is not on the grid");
  double sum = 0.0;
  int n = 0;
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double r = std::hypot(grid.x(i), grid.y(j));
      if (r >= reference.hertz.contact_radius) continue;
      sum += std::pow(qx(i, j) - reference.traction(r, tangential_load), 2);
      ++n;
    }
  COATFFT_REQUIRE(n > 0, "rms_traction_error: no cell inside the contact");
  return std::sqrt(sum / n) / (reference.friction * reference.hertz.max_pressure);
}

}  // namespace coatfft
