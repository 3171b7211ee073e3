#include "materials/material.hpp"

#include <cmath>

#include "core/error.hpp"

namespace coatfft {

Material::Material(double E, double nu) : E_(E), nu_(nu) {
  COATFFT_REQUIRE(std::isfinite(E) && E > 0, "Material: E = ", E,
                  " Pa, but Young's modulus must be finite and > 0");
  COATFFT_REQUIRE(E >= min_modulus && E <= max_modulus, "Material: E = ", E,
                  " Pa, but Young's modulus must lie in [", min_modulus, ", ", max_modulus,
                  "] Pa (rescale the units of the moduli and the loads)");
  COATFFT_REQUIRE(std::isfinite(nu) && nu > -1.0 && nu <= max_poisson_ratio, "Material: nu = ", nu,
                  ", but Poisson's ratio must be finite with -1 < nu <= ", max_poisson_ratio);
}

}  // namespace coatfft
