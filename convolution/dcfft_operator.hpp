#pragma once
// DC-FFT (Liu, Wang & Liu, Wear 243 (2000) 101): the linear convolution of the pressure with
// space-domain influence coefficients, computed exactly (to rounding) by a circular convolution on
// the zero-padded (2nx, 2ny) grid. Seed paper (Spinu 2021) section 3.
#include <string>

#include "convolution/fftw_plan.hpp"
#include "convolution/influence_kernel.hpp"
#include "convolution/surface_operator.hpp"

namespace coatfft {

/// Surface operator u = K * p (linear convolution) by DC-FFT for any InfluenceKernel (no symmetry
/// assumed). Everything is planned in the constructor: the kernel spectrum (with FFTW's 1/(4 nx ny)
/// folded in) and the FFTW plans on owned buffers; apply() only copies, transforms and multiplies.
class DcfftOperator final : public SurfaceOperator {
 public:
  /// `planning` is the FFTW planner effort; `threads` (>= 1) the FFTW threads per transform.
  explicit DcfftOperator(const InfluenceKernel& kernel, Planning planning = Planning::estimate,
                         int threads = 1);

  const Grid& grid() const override { return grid_; }
  /// Throws InvalidArgument unless `pressure` has shape (nx, ny) and does not alias
  /// `displacement`.
  void apply(const Field& pressure, Field& displacement) override;
  std::string name() const override { return "dcfft"; }
  using SurfaceOperator::apply;

  /// Wall-clock seconds the constructor took (kernel transform and FFTW planning).
  double setup_seconds() const { return setup_seconds_; }

 private:
  Grid grid_;
  std::ptrdiff_t mx_;  // padded sizes 2 nx, 2 ny
  std::ptrdiff_t my_;
  std::ptrdiff_t hx_;  // nx + 1 = mx/2 + 1 complex entries per r2c row
  FftwRealBuffer real_;
  FftwComplexBuffer spectrum_;
  FftwComplexBuffer kernel_hat_;
  FftwPlan forward_;
  FftwPlan backward_;
  double setup_seconds_ = 0.0;
};

}  // namespace coatfft
