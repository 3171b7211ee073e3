#pragma once
// The 2-D DFT of a real (nx, ny) field held in row slabs (distributed/slab.hpp), the steps FFTW-MPI
// takes, on unpadded rows: FFTW's r2c of each local row (along x), FFTW-MPI's transpose of the half
// spectrum's rows into columns, FFTW's c2c of each local column (along y). The spectrum stays
// transposed: this rank's columns kx0 <= i < kx0 + columns, each of ny entries, entry (i, j) at
// (i - kx0) ny + j. inverse() runs the steps backwards, unnormalised (nx ny times the field) as
// FFTW's c2r. Every step is collective: all ranks of the communicator call it together.
#include <complex>
#include <cstddef>
#include <utility>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/fft/planning.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"

namespace coatfft::detail {

/// FFTW's plan of `howmany` 1-D transforms, made by `make`: none (an empty plan) when this rank
/// holds no row or column to transform.
template <typename Make>
FftwPlan plan_many(std::ptrdiff_t howmany, int threads, Make&& make) {
  return howmany > 0 ? FftwPlan::create(threads, std::forward<Make>(make)) : FftwPlan();
}

/// Executes a plan of plan_many, unless it is empty.
inline void execute_if_planned(const FftwPlan& plan) {
  if (plan.valid()) plan.execute();
}

/// Executes a transpose's plan, adding its wall time to `seconds` (the communication between the
/// ranks, and the wait for the slowest).
void execute_timed(const FftwPlan& plan, double& seconds);

/// The 2-D DCT-I (FFTW's REDFT00 along both axes, unnormalised) of a real (n_rows, n_cols) array,
/// n_rows, n_cols >= 2, held by rows as fftw_mpi_local_size_many_transposed splits it: this rank's
/// `rows` rows of `in` (n_cols each) are transformed along x in place and transposed into `out`,
/// whose `columns` columns (n_rows each) are transformed along y. `in` is destroyed. Collective.
void dct1_rows_then_columns(const Communicator& comm, std::ptrdiff_t n_rows, std::ptrdiff_t n_cols,
                            std::ptrdiff_t rows, std::ptrdiff_t columns, double* in, double* out,
                            int threads);

/// slab_of, and the doubles FFTW-MPI asks a rank to allocate for each of the transposes' arrays.
Slab slab_of(const Communicator& comm, std::ptrdiff_t nx, std::ptrdiff_t ny,
             std::ptrdiff_t& doubles);

class SlabFft {
 public:
  /// `threads` (>= 1): FFTW's threads within this rank.
  SlabFft(const Communicator& comm, std::ptrdiff_t nx, std::ptrdiff_t ny,
          Planning planning = Planning::estimate, int threads = 1);

  const Slab& slab() const { return slab_; }
  /// The transposed half spectrum: columns x ny entries.
  std::complex<double>* spectrum() { return as_complex(columns_.data()); }
  /// The half spectrum's rows before the transpose: rows x (nx/2 + 1) entries.
  std::complex<double>* row_spectrum() { return as_complex(rows_.data()); }

  /// `field` (nx x rows, x fastest; kept) to spectrum().
  void forward(const double* field);
  /// spectrum() (consumed) to `field`, times nx ny.
  void inverse(double* field);
  /// The inverse of a half spectrum given by rows: row_spectrum() (consumed) to `field`.
  void inverse_from_rows(double* field);

  /// The wall time spent in the transposes so far [s]: the communication (and the wait for the
  /// slowest rank), which benchmarks report as a share of the transforms'.
  double transpose_seconds() const { return transpose_seconds_; }

 private:
  void rows_r2c(const double* field);
  void rows_c2r(double* field);
  void transpose(const FftwPlan& plan);
  void field_buffer();

  Slab slab_;
  FftwComplexBuffer rows_, columns_;
  FftwRealBuffer planned_field_;  // the row plans' buffer: freed after planning, made on demand
  int planned_alignment_ = 0;
  double transpose_seconds_ = 0.0;
  FftwPlan r2c_, c2r_, to_columns_, to_rows_, forward_y_, inverse_y_;
};

}  // namespace coatfft::detail
