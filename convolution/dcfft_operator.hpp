#pragma once
// DC-FFT (Liu, Wang & Liu, Wear 243 (2000) 101): the linear convolution of the pressure with
// space-domain influence coefficients, computed exactly (to rounding) as a circular convolution on
// the zero-padded (2nx, 2ny) grid. Seed paper (Spinu 2021) section 3.
#include <cstddef>
#include <string>
#include <vector>

#include "convolution/fftw_plan.hpp"
#include "convolution/influence_kernel.hpp"
#include "convolution/surface_operator.hpp"

namespace coatfft {

/// The spectrum of an even influence kernel on DC-FFT's padded (2nx, 2ny) lattice, given directly
/// instead of the coefficients: `values(jx, jy)` = sum over the wrapped offsets of
/// K(di, dj) cos(pi jx di / nx) cos(pi jy dj / ny) for 0 <= jx <= nx, 0 <= jy <= ny (the
/// unnormalised DFT, real and even). Whatever the spectrum implies at the offsets +-nx, +-ny is
/// irrelevant: those offsets never reach the cropped output of a grid of nx x ny cells.
struct EvenKernelSpectrum {
  Grid grid;
  Field values;  ///< shape (nx + 1, ny + 1) [m/Pa]
};

/// Surface operator u = K * p (linear convolution) by DC-FFT for any InfluenceKernel (no symmetry
/// assumed; an exactly even kernel such as Love's is detected and its real spectrum stored at a
/// quarter of the memory). Everything is planned in the constructor: the kernel spectrum (with
/// FFTW's 1/(4 nx ny) folded in) and the FFTW plans on owned buffers; apply() only copies,
/// transforms and multiplies. The padded transform is pruned: three quarters of the padded input
/// are zeros and three quarters of the padded output are discarded, so the x transforms run on
/// the ny data rows only and the y transforms on cache-sized column blocks.
class DcfftOperator final : public SurfaceOperator {
 public:
  /// `planning` is the FFTW planner effort; `threads` (>= 1) the threads of apply(): FFTW threads
  /// for the x transforms and as many workers for the blocks of y transforms.
  explicit DcfftOperator(const InfluenceKernel& kernel, Planning planning = Planning::estimate,
                         int threads = 1);

  /// From an even kernel's quarter (love_kernel_quarter): the same operator as from its
  /// wrap-around form, without that (2nx, 2ny) array. Throws InvalidArgument unless the quarter
  /// has shape (nx + 1, ny + 1) and finite entries.
  explicit DcfftOperator(const EvenInfluenceKernel& kernel, Planning planning = Planning::estimate,
                         int threads = 1);

  /// From the kernel's spectrum (skips the kernel transform: used where the coefficients would
  /// only be the inverse transform of a known spectrum, frf_dcfft_operator at alpha = 2). Throws
  /// InvalidArgument unless `spectrum.values` has shape (nx + 1, ny + 1) and is finite.
  explicit DcfftOperator(const EvenKernelSpectrum& spectrum, Planning planning = Planning::estimate,
                         int threads = 1);

  const Grid& grid() const override { return grid_; }
  /// Throws InvalidArgument unless `pressure` has shape (nx, ny) and does not alias
  /// `displacement`.
  void apply(const Field& pressure, Field& displacement) override;
  std::string name() const override { return "dcfft"; }
  using SurfaceOperator::apply;

  /// Wall-clock seconds the constructor took (kernel transform and FFTW planning) [s].
  double setup_seconds() const { return setup_seconds_; }
  /// True when the kernel was found exactly even in x and in y (real spectrum stored).
  bool even_kernel() const { return even_; }

 private:
  // One worker's scratch: a block of `block_` spectrum columns of all 2ny rows, column-major
  // (each column contiguous), with its own in-place y plans.
  struct Worker {
    FftwComplexBuffer block;
    FftwPlan forward_y;
    FftwPlan backward_y;
  };

  DcfftOperator(const Grid& grid, Planning planning, int threads);  // plans and buffers only
  // DCT-I of the (nx + 1) x (ny + 1) corner at `corner`, x fastest, columns `column_stride` apart.
  void compute_even_spectrum(const double* corner, std::ptrdiff_t column_stride);
  void compute_general_spectrum(const Field& wrapped);
  void convolve_columns(Worker& worker, std::ptrdiff_t first_block, std::ptrdiff_t end_block);

  Grid grid_;
  std::ptrdiff_t nx_;
  std::ptrdiff_t ny_;
  std::ptrdiff_t mx_;  // padded sizes 2 nx, 2 ny
  std::ptrdiff_t my_;
  std::ptrdiff_t hx_;     // nx + 1: complex entries per r2c row, also the spectrum's row length
  std::ptrdiff_t block_;  // spectrum columns per y-transform block
  std::ptrdiff_t nb_blocks_;
  int threads_;
  bool even_ = false;
  // The ny data rows: real view with row stride 2 hx (in-place r2c), complex view with row
  // stride hx. Holds the pressure, its x spectrum, the filtered x spectrum, the displacement.
  FftwComplexBuffer rows_;
  FftwPlan forward_x_;
  FftwPlan backward_x_;
  // Kernel spectrum times 1/(4 nx ny), column-major [kx][ky]: real hx x (ny + 1) when even_
  // (ky > ny mirrors 2ny - ky), else complex hx x 2ny.
  FftwRealBuffer kernel_even_;
  FftwComplexBuffer kernel_general_;
  std::vector<Worker> workers_;
  double setup_seconds_ = 0.0;
};

}  // namespace coatfft
