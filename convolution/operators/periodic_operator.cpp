#include "convolution/operators/periodic_operator.hpp"

#include <cmath>

#include "convolution/fft/detail/spectral_filter.hpp"
#include "convolution/kernels/detail/coarse_kernel.hpp"
#include "core/error.hpp"

namespace coatfft {

PeriodicOperator::~PeriodicOperator() = default;

PeriodicOperator::PeriodicOperator(const Grid& grid, const Field& kernel, Method method,
                                   Planning planning, Precision precision, int threads)
    : grid_(grid), method_(method), precision_(precision), threads_(threads) {
  COATFFT_REQUIRE(kernel.rows() == grid.nx() && kernel.cols() == grid.ny(),
                  "PeriodicOperator: the kernel is not of the grid's shape");
  COATFFT_REQUIRE(kernel.allFinite(),
                  "PeriodicOperator: the kernel has a value that is not finite");
  COATFFT_REQUIRE(threads >= 1, "PeriodicOperator: threads = ", threads, " must be >= 1");
  // The kernel's spectrum in double precision, normalised by the cell count for the round trip;
  // a quarter of the modes stored (the kernel is even in both offsets).
  filter_ = detail::SpectralFilter::create(grid, planning, precision, threads);
  multiplier_ = std::make_unique<detail::EvenMultiplier>(
      filter_->even_spectrum(kernel.data(), 1.0 / static_cast<double>(kernel.size())));
}

void PeriodicOperator::apply(const Field& pressure, Field& displacement) {
  COATFFT_REQUIRE(pressure.rows() == grid_.nx() && pressure.cols() == grid_.ny(),
                  "PeriodicOperator::apply: the pressure is not of the grid's shape");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "PeriodicOperator::apply: the displacement must not alias the pressure");
  displacement.resize(grid_.nx(), grid_.ny());
  filter_->apply(pressure.data(), displacement.data(), *multiplier_);
  // Every displacement is a sum over every mode, and each mode over every pressure, so one value
  // that is not finite in the pressure makes every displacement NaN or Inf: one cell checks them
  // all, where a pass over the pressure would cost a tenth of an application on the solver's
  // hot path (the multiplier is finite, checked when it was built).
  COATFFT_REQUIRE(std::isfinite(displacement(0, 0)),
                  "PeriodicOperator::apply: the pressure has a value that is not finite (or too "
                  "large for the displacement to be)");
}

std::unique_ptr<SurfaceOperator> PeriodicOperator::coarsened() {
  if (grid_.nx() % 2 != 0 || grid_.ny() % 2 != 0) return nullptr;
  const Field kernel = unit_response();
  const Grid coarse(grid_.nx() / 2, grid_.ny() / 2, grid_.lx(), grid_.ly());
  return std::make_unique<PeriodicOperator>(coarse, detail::coarse_periodic_kernel(kernel), method_,
                                            Planning::estimate, precision_, threads_);
}

}  // namespace coatfft
