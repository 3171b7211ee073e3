#include "frf/frf.hpp"

#include "core/error.hpp"

namespace coatfft {

void Frf::evaluate(std::span<const double> k, std::span<double> h) const {
  COATFFT_REQUIRE(k.size() == h.size(), "Frf::evaluate: ", k.size(), " wavenumbers but ", h.size(),
                  " outputs; the sizes must be equal");
  for (std::size_t i = 0; i < k.size(); ++i) h[i] = (*this)(k[i]);
}

}  // namespace coatfft
