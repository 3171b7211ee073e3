#include "validation/winkler_dugdale.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "materials/material.hpp"

namespace coatfft {

double thin_film_stiffness(const Material& film, double thickness) {
  COATFFT_REQUIRE(thickness > 0, "thin_film_stiffness: thickness must be > 0");
  const double nu = film.poisson_ratio();
  COATFFT_REQUIRE(nu < 0.5, "thin_film_stiffness: an incompressible film has no Winkler limit");
  const double constrained = film.youngs_modulus() * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  return constrained / thickness;
}

WinklerDugdale::WinklerDugdale(double radius, double stiffness, double work_of_adhesion,
                               double range)
    : radius_(radius),
      stiffness_(stiffness),
      work_(work_of_adhesion),
      range_(range),
      strength_(work_of_adhesion / range) {
  COATFFT_REQUIRE(radius > 0 && stiffness > 0 && work_of_adhesion > 0 && range > 0,
                  "WinklerDugdale: radius, stiffness, work of adhesion and range must be > 0");
}

double WinklerDugdale::load_at_approach(double delta) const {
  const double s = strength_ / stiffness_;  // the stretch at which a ring lets go
  const double two_pi_r = 2 * std::numbers::pi * radius_;
  if (delta <= -s - range_) return 0.0;
  if (delta <= -s) return -two_pi_r * strength_ * (delta + s + range_);
  return two_pi_r * (-work_ + 0.5 * stiffness_ * (delta * delta - s * s));
}

double WinklerDugdale::contact_radius(double delta) const {
  const double x = delta + strength_ / stiffness_;
  return x > 0 ? std::sqrt(2 * radius_ * x) : 0.0;
}

double WinklerDugdale::cohesive_radius(double delta) const {
  const double x = delta + strength_ / stiffness_ + range_;
  return x > 0 ? std::sqrt(2 * radius_ * x) : 0.0;
}

double WinklerDugdale::approach_at_zero_load() const {
  // -w + k (delta^2 - s^2) / 2 = 0 on delta > 0.
  const double s = strength_ / stiffness_;
  return std::sqrt(s * s + 2 * work_ / stiffness_);
}

}  // namespace coatfft
