#include "validation/hertz_contact.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace coatfft {

namespace {

void require_positive(double value, const char* what) {
  COATFFT_REQUIRE(std::isfinite(value) && value > 0, what, " = ", value,
                  ", but it must be finite and > 0");
}

}  // namespace

double composite_modulus(const Material& body1, const Material& body2) {
  return 1.0 / (1.0 / body1.plane_strain_modulus() + 1.0 / body2.plane_strain_modulus());
}

double HertzSphere::pressure(double r) const {
  const double s = r / contact_radius;
  return s < 1.0 ? max_pressure * std::sqrt(1.0 - s * s) : 0.0;
}

HertzSphere hertz_sphere_for_load(double load, double radius, double plane_strain_modulus) {
  require_positive(load, "hertz_sphere_for_load: load [N]");
  require_positive(radius, "hertz_sphere_for_load: radius [m]");
  require_positive(plane_strain_modulus, "hertz_sphere_for_load: plane-strain modulus [Pa]");
  const double a = std::cbrt(3.0 * load * radius / (4.0 * plane_strain_modulus));
  return {load, a, 3.0 * load / (2.0 * std::numbers::pi * a * a), a * a / radius};
}

HertzSphere hertz_sphere_for_approach(double approach, double radius, double plane_strain_modulus) {
  require_positive(approach, "hertz_sphere_for_approach: approach [m]");
  require_positive(radius, "hertz_sphere_for_approach: radius [m]");
  require_positive(plane_strain_modulus, "hertz_sphere_for_approach: plane-strain modulus [Pa]");
  const double a = std::sqrt(radius * approach);
  const double load =
      4.0 / 3.0 * plane_strain_modulus * std::sqrt(radius) * std::pow(approach, 1.5);
  return {load, a, 3.0 * load / (2.0 * std::numbers::pi * a * a), approach};
}

double flat_punch_load(double radius, double approach, double plane_strain_modulus) {
  require_positive(radius, "flat_punch_load: radius [m]");
  require_positive(approach, "flat_punch_load: approach [m]");
  require_positive(plane_strain_modulus, "flat_punch_load: plane-strain modulus [Pa]");
  return 2.0 * radius * plane_strain_modulus * approach;
}

double flat_punch_pressure(double r, double radius, double load) {
  require_positive(radius, "flat_punch_pressure: radius [m]");
  require_positive(load, "flat_punch_pressure: load [N]");
  COATFFT_REQUIRE(std::isfinite(r) && std::abs(r) < radius, "flat_punch_pressure: r = ", r,
                  " m, but it must lie inside the punch, |r| < ", radius, " m");
  return load / (2.0 * std::numbers::pi * radius * std::sqrt(radius * radius - r * r));
}

}  // namespace coatfft
