#pragma once
// The surface displacement of a periodic surface: the circular convolution of the pressure with
// the periodic influence coefficients (convolution/kernels/periodic_kernel.hpp) by FFTs of the
// grid's own size (no padding), exact for a cell-wise constant pressure repeated over the periods.
// The displacement has zero mean over the period (docs/theory.md 4.8).
#include <memory>

#include "../../core/types.hpp"
#include "../fft/planning.hpp"
#include "surface_operator.hpp"

namespace coatfft {

namespace detail {
class SpectralFilter;
struct EvenMultiplier;
}  // namespace detail

class PeriodicOperator final : public SurfaceOperator {
 public:
  /// `kernel`: the (nx, ny) periodic coefficients of `grid` (even, zero mean); `method` what
  /// built them (reported by method()); `precision` that of the FFTs (the kernel's spectrum is
  /// always computed in double); `threads` (>= 1) the FFTW threads of apply(). InvalidArgument
  /// for a kernel of another shape or with a value that is not finite.
  PeriodicOperator(const Grid& grid, const Field& kernel, Method method,
                   Planning planning = Planning::estimate,
                   Precision precision = Precision::double_precision, int threads = 1);
  ~PeriodicOperator() override;

  const Grid& grid() const override { return grid_; }
  void apply(const Field& pressure, Field& displacement) override;
  Method method() const override { return method_; }
  Precision precision() const { return precision_; }
  bool periodic() const override { return true; }
  /// The Galerkin coarse operator (SurfaceOperator::coarsened), same precision and threads,
  /// FFTW_ESTIMATE plans.
  std::unique_ptr<SurfaceOperator> coarsened() override;
  using SurfaceOperator::apply;
  /// Its transforms: a preconditioner on the same grid shares them (their spectrum buffer is
  /// scratch of each application).
  const std::shared_ptr<detail::SpectralFilter>& spectral_filter() const { return filter_; }

 private:
  Grid grid_;
  Method method_;
  Precision precision_;
  int threads_;
  std::shared_ptr<detail::SpectralFilter> filter_;
  std::unique_ptr<detail::EvenMultiplier> multiplier_;  // the kernel's spectrum / (nx ny)
};

}  // namespace coatfft
