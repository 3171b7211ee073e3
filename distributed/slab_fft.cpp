#include "distributed/detail/slab_fft.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <chrono>

#include "core/detail/timing.hpp"
#include "distributed/detail/mpi_handle.hpp"

namespace coatfft::detail {

SlabFft::SlabFft(const Communicator& comm, std::ptrdiff_t nx, std::ptrdiff_t ny, Planning planning,
                 int threads) {
  std::ptrdiff_t doubles = 0;
  slab_ = slab_of(comm, nx, ny, doubles);
  const std::ptrdiff_t hx = nx / 2 + 1;
  const std::ptrdiff_t rows = slab_.rows, columns = slab_.columns;
  // FFTW-MPI's allocation covers both layouts (and the transposes' needs); at least one entry.
  const auto complex_entries = static_cast<std::size_t>(std::max<std::ptrdiff_t>(doubles / 2, 1));
  rows_ = FftwComplexBuffer(complex_entries);
  columns_ = FftwComplexBuffer(complex_entries);
  planned_field_ = FftwRealBuffer(static_cast<std::size_t>(std::max<std::ptrdiff_t>(nx * rows, 1)));
  planned_alignment_ = fftw_alignment_of(planned_field_.data());
  // Out of place, with FFTW_DESTROY_INPUT: FFTW-MPI's transposes may use their input as scratch.
  const unsigned flags = fftw_flags(planning) | FFTW_DESTROY_INPUT;
  const int n_x = static_cast<int>(nx), n_y = static_cast<int>(ny), h = static_cast<int>(hx);
  r2c_ = plan_many(rows, threads, [&] {
    return fftw_plan_many_dft_r2c(1, &n_x, static_cast<int>(rows), planned_field_.data(), nullptr,
                                  1, n_x, rows_.data(), nullptr, 1, h, fftw_flags(planning));
  });
  c2r_ = plan_many(rows, threads, [&] {
    return fftw_plan_many_dft_c2r(1, &n_x, static_cast<int>(rows), rows_.data(), nullptr, 1, h,
                                  planned_field_.data(), nullptr, 1, n_x, flags);
  });
  to_columns_ = FftwPlan::create(threads, [&] {
    return fftw_mpi_plan_many_transpose(ny, hx, 2, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                        reinterpret_cast<double*>(rows_.data()),
                                        reinterpret_cast<double*>(columns_.data()), mpi_comm(comm),
                                        flags);
  });
  to_rows_ = FftwPlan::create(threads, [&] {
    return fftw_mpi_plan_many_transpose(hx, ny, 2, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                        reinterpret_cast<double*>(columns_.data()),
                                        reinterpret_cast<double*>(rows_.data()), mpi_comm(comm),
                                        flags);
  });
  for (int sign : {FFTW_FORWARD, FFTW_BACKWARD}) {
    (sign == FFTW_FORWARD ? forward_y_ : inverse_y_) = plan_many(columns, threads, [&] {
      return fftw_plan_many_dft(1, &n_y, static_cast<int>(columns), columns_.data(), nullptr, 1,
                                n_y, columns_.data(), nullptr, 1, n_y, sign, fftw_flags(planning));
    });
  }
  planned_field_ = FftwRealBuffer();  // a field's memory; only a misaligned field needs it again
}

// FFTW's allocator gives the planned buffer's alignment again.
void SlabFft::field_buffer() {
  if (planned_field_.size() == 0)
    planned_field_ = FftwRealBuffer(static_cast<std::size_t>(slab_.cells()));
}

// The row transforms read and write the caller's field itself (FFTW's new-array execute) when it
// is aligned as the planned buffer was, as Eigen's fields are; otherwise through that buffer.
void SlabFft::rows_r2c(const double* field) {
  if (!r2c_.valid()) return;
  auto* in = const_cast<double*>(field);  // an out-of-place r2c keeps its input
  if (fftw_alignment_of(in) == planned_alignment_) {
    fftw_execute_dft_r2c(r2c_.get(), in, rows_.data());
    return;
  }
  field_buffer();
  std::copy_n(field, slab_.cells(), planned_field_.data());
  r2c_.execute();
}

void SlabFft::rows_c2r(double* field) {
  if (!c2r_.valid()) return;
  if (fftw_alignment_of(field) == planned_alignment_) {
    fftw_execute_dft_c2r(c2r_.get(), rows_.data(), field);
    return;
  }
  field_buffer();
  c2r_.execute();
  std::copy_n(planned_field_.data(), slab_.cells(), field);
}

void execute_timed(const FftwPlan& plan, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  plan.execute();
  seconds += seconds_since(start);
}

void SlabFft::transpose(const FftwPlan& plan) {
  execute_timed(plan, transpose_seconds_);
}

void SlabFft::forward(const double* field) {
  rows_r2c(field);
  transpose(to_columns_);
  execute_if_planned(forward_y_);
}

void SlabFft::inverse(double* field) {
  execute_if_planned(inverse_y_);
  transpose(to_rows_);
  rows_c2r(field);
}

void SlabFft::inverse_from_rows(double* field) {
  transpose(to_columns_);
  inverse(field);
}

}  // namespace coatfft::detail

namespace coatfft::detail {

void dct1_rows_then_columns(const Communicator& comm, std::ptrdiff_t n_rows, std::ptrdiff_t n_cols,
                            std::ptrdiff_t rows, std::ptrdiff_t columns, double* in, double* out,
                            int threads) {
  const fftw_r2r_kind kind = FFTW_REDFT00;
  const int nx = static_cast<int>(n_cols), ny = static_cast<int>(n_rows);
  const FftwPlan along_x = plan_many(rows, threads, [&] {
    return fftw_plan_many_r2r(1, &nx, static_cast<int>(rows), in, nullptr, 1, nx, in, nullptr, 1,
                              nx, &kind, FFTW_ESTIMATE);
  });
  const FftwPlan transpose = FftwPlan::create(threads, [&] {
    return fftw_mpi_plan_many_transpose(n_rows, n_cols, 1, FFTW_MPI_DEFAULT_BLOCK,
                                        FFTW_MPI_DEFAULT_BLOCK, in, out, mpi_comm(comm),
                                        FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
  const FftwPlan along_y = plan_many(columns, threads, [&] {
    return fftw_plan_many_r2r(1, &ny, static_cast<int>(columns), out, nullptr, 1, ny, out, nullptr,
                              1, ny, &kind, FFTW_ESTIMATE);
  });
  execute_if_planned(along_x);
  transpose.execute();
  execute_if_planned(along_y);
}

}  // namespace coatfft::detail
