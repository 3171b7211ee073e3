#pragma once
// The cost model of the automatic method choice (docs/auto.md, section 3): predicted setup and
// application times of each operator of make_operator, from counts of the work it does, with
// constants fitted to bench_auto_calibration (bench/results/auto_calibration.csv; one thread,
// FFTW_ESTIMATE). The predictions serve to rank the methods and to tell the user what a run
// will cost (`coatfft check`); they are measured against the runs in docs/auto.md (within 2x
// on the examples).
#include <cstddef>

#include "../convolution/kernels/split_frf_kernel.hpp"
#include "../core/grid.hpp"

namespace coatfft {

/// One application of a DC-FFT operator on an (fft_nx, fft_ny) padded lattice [s], on
/// `threads` threads.
double predicted_dcfft_apply_seconds(std::ptrdiff_t fft_nx, std::ptrdiff_t fft_ny, int threads);

/// One application of direct summation on `grid` [s].
double predicted_direct_apply_seconds(const Grid& grid);

/// Setup of Love's DC-FFT (coefficients, kernel transform, plans) [s].
double predicted_love_setup_seconds(const Grid& grid, std::ptrdiff_t fft_nx, std::ptrdiff_t fft_ny);

/// Setup of frf-spectral or frf-dcfft on an (mx, my) extended lattice [s], without g(0) and
/// the prediction of their error: the FRF sampled once per point of an eighth of the lattice
/// (sample_frf_half_spectrum's symmetries), plans and transforms as Love's DC-FFT.
double predicted_lattice_setup_seconds(const Grid& grid, std::ptrdiff_t mx, std::ptrdiff_t my);

/// Setup of frf-split with the counted `work` of its kernel [s], on `threads` threads.
double predicted_split_setup_seconds(const Grid& grid, const SplitKernelWork& work, int threads);

/// FFTW's start in a process: the first plan of a process costs this much more than the later
/// ones (its planner and codelet tables; bench_auto_calibration's first build of an 8 x 8 dcfft
/// operator against its later ones) [s]. A command-line run pays it once; a program that builds
/// operators repeatedly pays it only for its first.
double fftw_start_seconds();

/// Parallel speed-up assumed for `threads` threads on a transform of `points` points: none
/// below 2^18 points (the threads' start-up eats the gain), 0.7 per extra thread above.
double assumed_speedup(double points, int threads);

}  // namespace coatfft
