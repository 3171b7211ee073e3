#pragma once
// DC-FFT (Liu, Wang & Liu, Wear 243 (2000) 101): the linear convolution of the pressure with
// space-domain influence coefficients, computed exactly (to rounding) as a circular convolution on
// a zero-padded (mx, my) grid. Spinu (2021), section 3. Any period M >= 2n - 1 is exact: the
// offsets d in [-(n - 1), n - 1] sit at the slots d and M + d with zeros between, and never
// overlap. The coefficient form takes the smallest even 7-smooth M (core/detail/fft_size.hpp),
// since 2n itself can be a slow FFT length (an application on 2 x 127 cost 4.5-5 times one on 2 x
// 128; docs/benchmarks.md, "Fast FFT sizes"); the spectrum form keeps M = 2n, the only lattice its
// samples are given on.
#include <cstddef>
#include <string>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/surface_operator.hpp"

namespace coatfft {

/// Surface operator u = K * p (linear convolution) by DC-FFT for an influence kernel in either of
/// its forms. Everything is planned in the constructor: the kernel's real spectrum (a DCT-I of the
/// coefficient quarter, or the given spectrum quarter, with FFTW's 1/(mx my) folded in) and the
/// FFTW plans on owned buffers; apply() only copies, transforms and multiplies. The padded
/// transform is pruned: three quarters (or more) of the padded input are zeros and as much of the
/// padded output is discarded, so the x transforms run on the ny data rows only and the y
/// transforms on cache-sized column blocks.
class DcfftOperator final : public SurfaceOperator {
 public:
  /// `planning` is the FFTW planner effort; `threads` (>= 1) the threads of apply(): FFTW threads
  /// for the x transforms and as many workers for the blocks of y transforms. The spectrum form
  /// skips the kernel transform (frf-dcfft at alpha = 2 samples the spectrum directly).
  explicit DcfftOperator(const InfluenceKernel& kernel, Planning planning = Planning::estimate,
                         int threads = 1);

  const Grid& grid() const override { return grid_; }
  /// Throws InvalidArgument unless `pressure` has shape (nx, ny) and does not alias
  /// `displacement`.
  void apply(const Field& pressure, Field& displacement) override;
  Method method() const override { return method_; }
  /// The Galerkin coarse operator (SurfaceOperator::coarsened) in coefficient form, same
  /// threads, FFTW_ESTIMATE plans.
  std::unique_ptr<SurfaceOperator> coarsened() override;
  using SurfaceOperator::apply;

  /// Wall-clock seconds the constructor took (kernel transform and FFTW planning) [s].
  double setup_seconds() const { return setup_seconds_; }
  /// The padded transform lengths mx, my of apply().
  std::ptrdiff_t padded_nx() const { return mx_; }
  std::ptrdiff_t padded_ny() const { return my_; }

  /// The padded length of an axis of n >= 1 cells for a kernel of form `form`: 2n for the
  /// spectrum form, the smallest even 7-smooth length >= 2n - 1 for coefficients (throws
  /// InvalidArgument for n < 1). What memory estimates should assume.
  static std::ptrdiff_t padded_size(std::ptrdiff_t n, InfluenceKernel::Form form);

 private:
  // One worker's scratch: a block of `block_` spectrum columns of all my rows, column-major
  // (each column contiguous), with its own in-place y plans.
  struct Worker {
    FftwComplexBuffer block;
    FftwPlan forward_y;
    FftwPlan backward_y;
  };

  void plan_transforms(Planning planning);
  // The kernel spectrum from the coefficient quarter (a DCT-I) or from the spectrum quarter.
  void transform_coefficients(const Field& quarter);
  void store_spectrum(const Field& quarter);
  void convolve_columns(Worker& worker, std::ptrdiff_t first_block, std::ptrdiff_t end_block);

  Grid grid_;
  std::ptrdiff_t nx_;
  std::ptrdiff_t ny_;
  std::ptrdiff_t mx_;  // padded sizes (padded_size), even
  std::ptrdiff_t my_;
  std::ptrdiff_t hx_;     // mx/2 + 1: complex entries per r2c row, also the spectrum's row length
  std::ptrdiff_t hy_;     // my/2: the spectrum's rows ky > hy mirror my - ky
  std::ptrdiff_t block_;  // spectrum columns per y-transform block
  std::ptrdiff_t nb_blocks_;
  int threads_;
  Method method_;
  // The ny data rows: real view with row stride 2 hx (in-place r2c), complex view with row
  // stride hx. Holds the pressure, its x spectrum, the filtered x spectrum, the displacement.
  FftwComplexBuffer rows_;
  FftwPlan forward_x_;
  FftwPlan backward_x_;
  // Kernel spectrum times 1/(mx my), real, column-major [kx][ky], hx x (hy + 1): the rows
  // ky > hy mirror my - ky.
  FftwRealBuffer kernel_spectrum_;
  std::vector<Worker> workers_;
  double setup_seconds_ = 0.0;
};

}  // namespace coatfft
