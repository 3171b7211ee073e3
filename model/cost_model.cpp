#include "model/cost_model.hpp"

#include <algorithm>
#include <cmath>

namespace coatfft {

namespace {

// Constants fitted by bench_auto_calibration (bench/results/auto_calibration.csv, relative least
// squares; docs/auto.md section 3) [s per unit of work].
constexpr double apply_fixed = 0.0;              // dropped by the fit (negative)
constexpr double apply_per_point_log = 2.4e-10;  // per P log2 P of the padded lattice
constexpr double fftw_start = 8.4e-3;            // the first plan of a process, once
constexpr double direct_per_pair = 5.4e-10;      // per (cell, cell) pair (bench/results/sweep.csv)
constexpr double love_fixed = 1.4e-5;
constexpr double love_per_cell = 8.9e-8;
constexpr double love_per_point_log = 0.0;  // dropped by the fit (negative)
// One FRF evaluation: 0.05 us (one coating) to 0.6 us (five) in bench/results/frf_eval.csv.
constexpr double frf_sample = 2e-7;
constexpr double split_fixed = 9.0e-4;
constexpr double split_per_cell = 1.9e-8;
constexpr double split_per_fold_term = 1.06e-8;
constexpr double split_per_hankel = 2.2e-8;

double point_log(std::ptrdiff_t fft_nx, std::ptrdiff_t fft_ny) {
  const double p = static_cast<double>(fft_nx) * static_cast<double>(fft_ny);
  return p > 1 ? p * std::log2(p) : 1.0;
}

}  // namespace

double fftw_start_seconds() {
  return fftw_start;
}

double assumed_speedup(double points, int threads) {
  if (threads <= 1 || points < 262144.0) return 1.0;
  return 1.0 + 0.7 * (threads - 1);
}

double predicted_dcfft_apply_seconds(std::ptrdiff_t fft_nx, std::ptrdiff_t fft_ny, int threads) {
  const double points = static_cast<double>(fft_nx) * static_cast<double>(fft_ny);
  return apply_fixed +
         apply_per_point_log * point_log(fft_nx, fft_ny) / assumed_speedup(points, threads);
}

double predicted_direct_apply_seconds(const Grid& grid) {
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  return direct_per_pair * cells * cells;
}

double predicted_love_setup_seconds(const Grid& grid, std::ptrdiff_t fft_nx,
                                    std::ptrdiff_t fft_ny) {
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  return love_fixed + love_per_cell * cells + love_per_point_log * point_log(fft_nx, fft_ny);
}

double predicted_lattice_setup_seconds(const Grid& grid, std::ptrdiff_t mx, std::ptrdiff_t my) {
  const double samples = static_cast<double>(mx) * static_cast<double>(my) / 8.0;
  return frf_sample * samples + predicted_love_setup_seconds(grid, mx, my);
}

double predicted_split_setup_seconds(const Grid& grid, const SplitKernelWork& work, int threads) {
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  // The cell rule's nodes (work.cell_nodes) and the transform are absorbed by the per-cell
  // constant: collinear with the cells in the calibration, they got no weight of their own.
  const double kernel =
      split_per_fold_term * work.fold_terms + split_per_hankel * work.hankel_evaluations;
  // The kernel's loops run on the threads (split_frf_kernel); their speed-up is taken as the
  // transforms'.
  const double speedup = assumed_speedup(cells * 4.0, threads);
  return split_fixed + split_per_cell * cells + kernel / speedup;
}

}  // namespace coatfft
