#include "convolution/frf_dcfft_operator.hpp"

#include <cmath>
#include <numbers>

#include "convolution/frf_influence_kernel.hpp"
#include "convolution/frf_spectral_operator.hpp"
#include "core/error.hpp"

namespace coatfft {

std::unique_ptr<DcfftOperator> frf_dcfft_operator(const Grid& grid, const Frf& frf, double alpha,
                                                  const G0Result& g0, Planning planning,
                                                  int threads) {
  constexpr const char* who = "frf_dcfft_operator";
  const std::ptrdiff_t mx = extended_size(grid.nx(), alpha, 2.0, who);
  const std::ptrdiff_t my = extended_size(grid.ny(), alpha, 2.0, who);
  if (mx != 2 * grid.nx() || my != 2 * grid.ny())
    return std::make_unique<DcfftOperator>(frf_influence_kernel(grid, frf, alpha, g0, threads),
                                           planning, threads);
  COATFFT_REQUIRE(std::isfinite(g0.value), who, ": g(0) = ", g0.value,
                  " m/Pa, but it must be finite");
  COATFFT_REQUIRE(threads >= 1, who, ": threads = ", threads, ", but must be >= 1");
  EvenKernelSpectrum spectrum{grid,
                              detail::frf_cell_spectrum_quarter(grid, frf, mx, my, g0, threads)};
  return std::make_unique<DcfftOperator>(spectrum, planning, threads);
}

std::unique_ptr<DcfftOperator> frf_dcfft_operator(const Grid& grid, const Frf& frf, double alpha,
                                                  G0Method g0_method, double g0_tolerance,
                                                  G0Result* g0_used, Planning planning,
                                                  int threads) {
  using std::numbers::pi;
  constexpr const char* who = "frf_dcfft_operator";
  const auto mx = static_cast<double>(extended_size(grid.nx(), alpha, 2.0, who));
  const auto my = static_cast<double>(extended_size(grid.ny(), alpha, 2.0, who));
  const G0Result g0 = compute_g0(frf, 2.0 * pi / (mx * grid.dx()), 2.0 * pi / (my * grid.dy()),
                                 g0_method, g0_tolerance);
  if (g0_used != nullptr) *g0_used = g0;
  return frf_dcfft_operator(grid, frf, alpha, g0, planning, threads);
}

}  // namespace coatfft
