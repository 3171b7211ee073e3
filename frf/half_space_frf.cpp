#include "frf/half_space_frf.hpp"

#include <cmath>

#include "core/error.hpp"

namespace coatfft {

HalfSpaceFrf::HalfSpaceFrf(const Material& material) : c_(2.0 / material.plane_strain_modulus()) {}

double HalfSpaceFrf::operator()(double k) const {
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, "HalfSpaceFrf: k = ", k,
                  " rad/m, but the wavenumber must be finite and > 0");
  const double h = c_ / k;
  COATFFT_REQUIRE(std::isfinite(h), "HalfSpaceFrf: H(k = ", k, " rad/m) overflows");
  return h;
}

}  // namespace coatfft
