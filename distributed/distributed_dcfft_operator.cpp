#include "distributed/distributed_dcfft_operator.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <vector>

#include "convolution/fft/fftw_plan.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "distributed/slab_fft.hpp"

namespace coatfft {

struct DistributedDcfftOperator::Transforms {
  Slab slab;                         // the grid's rows; columns of the (nx + 1)-entry half spectrum
  FftwRealBuffer padded;             // rows x 2nx: each row, then nx zeros
  FftwComplexBuffer rows, columns;   // rows x (nx + 1) and columns x ny (FFTW-MPI's allocation)
  FftwComplexBuffer padded_columns;  // columns x 2ny: each column, then ny zeros
  std::vector<double> multiplier;    // the coefficients' (real) spectrum / (4 nx ny)
  FftwPlan r2c, c2r, to_columns, to_rows, forward_y, inverse_y;
  double transpose_seconds = 0.0;
};

namespace {

std::size_t entries(std::ptrdiff_t n) {
  return static_cast<std::size_t>(std::max<std::ptrdiff_t>(n, 1));
}

// This rank's rows of the (2nx, 2ny) wrap-around array of Love's coefficients (slot d for d >= 0,
// 2n + d for d < 0, slots nx and ny 0: InfluenceKernel::wrapped), by the slab transform of the
// padded grid to its spectrum, over 4 nx ny: the spectrum's columns are the operator's. The array
// is even in both offsets, so its spectrum is real: its real part is kept.
std::vector<double> love_spectrum(const Communicator& comm, const Grid& g, double e_star,
                                  const Slab& slab, Planning planning, int threads) {
  const std::ptrdiff_t nx = g.nx(), ny = g.ny();
  detail::SlabFft fft(comm, 2 * nx, 2 * ny, planning, threads);
  const Slab& s = fft.slab();
  COATFFT_REQUIRE(s.kx0 == slab.kx0 && s.columns == slab.columns,
                  "DistributedDcfftOperator: FFTW-MPI split the padded grid's columns otherwise");
  Field k = s.field();
  detail::parallel_for(0, s.rows, threads, [&](std::ptrdiff_t r) {
    const std::ptrdiff_t j = s.y0 + r;
    if (j == ny) return;  // the slot between the offsets +-(ny - 1)
    std::vector<double> row(static_cast<std::size_t>(nx));
    detail::love_influence_row(static_cast<double>(std::abs(j < ny ? j : j - 2 * ny)) * g.dy(),
                               g.dx(), g.dy(), nx, row.data());
    for (std::ptrdiff_t i = 0; i < nx; ++i) k(i, r) = row[std::size_t(i)] / e_star;
    for (std::ptrdiff_t m = 1; m < nx; ++m) k(2 * nx - m, r) = row[std::size_t(m)] / e_star;
  });
  fft.forward(k.data());
  const double norm = 1.0 / static_cast<double>(4 * nx * ny);
  std::vector<double> m(static_cast<std::size_t>(s.columns * s.ny));
  for (std::size_t n = 0; n < m.size(); ++n) m[n] = norm * fft.spectrum()[n].real();
  return m;
}

}  // namespace

DistributedDcfftOperator::~DistributedDcfftOperator() = default;

DistributedDcfftOperator::DistributedDcfftOperator(const Communicator& comm, const Grid& grid,
                                                   double plane_strain_modulus, Planning planning,
                                                   int threads)
    : DistributedOperator(comm), grid_(grid), t_(std::make_unique<Transforms>()) {
  COATFFT_REQUIRE(std::isfinite(plane_strain_modulus) && plane_strain_modulus > 0,
                  "DistributedDcfftOperator: E* = ", plane_strain_modulus,
                  " Pa, but it must be finite and > 0");
  COATFFT_REQUIRE(threads >= 1, "DistributedDcfftOperator: threads = ", threads, " must be >= 1");
  Transforms& t = *t_;
  const std::ptrdiff_t nx = grid.nx(), ny = grid.ny(), hx = nx + 1;
  // The half spectrum of a padded row has nx + 1 entries: the slabs of a (2nx, ny) grid.
  std::ptrdiff_t doubles = 0;
  t.slab = detail::slab_of(comm, 2 * nx, ny, doubles);
  t.slab.nx = nx;
  const std::ptrdiff_t rows = t.slab.rows, columns = t.slab.columns;
  t.padded = FftwRealBuffer(entries(2 * nx * rows));
  t.rows = FftwComplexBuffer(entries(doubles / 2));
  t.columns = FftwComplexBuffer(entries(doubles / 2));
  t.padded_columns = FftwComplexBuffer(entries(2 * ny * columns));
  std::fill_n(t.padded.data(), t.padded.size(), 0.0);
  std::fill_n(as_complex(t.padded_columns.data()), t.padded_columns.size(),
              std::complex<double>(0.0));
  const unsigned flags = fftw_flags(planning);
  // Out of place, with FFTW_DESTROY_INPUT where the input is rewritten before its next use.
  const unsigned destroy = flags | FFTW_DESTROY_INPUT;
  const int n2x = static_cast<int>(2 * nx), n2y = static_cast<int>(2 * ny), h = int(hx);
  t.r2c = detail::plan_many(rows, threads, [&] {
    return fftw_plan_many_dft_r2c(1, &n2x, int(rows), t.padded.data(), nullptr, 1, n2x,
                                  t.rows.data(), nullptr, 1, h, flags);
  });
  t.c2r = detail::plan_many(rows, threads, [&] {
    return fftw_plan_many_dft_c2r(1, &n2x, int(rows), t.rows.data(), nullptr, 1, h, t.padded.data(),
                                  nullptr, 1, n2x, destroy);
  });
  const auto transpose = [&](std::ptrdiff_t n0, std::ptrdiff_t n1, FftwComplexBuffer& in,
                             FftwComplexBuffer& out) {
    return FftwPlan::create(threads, [&] {
      return fftw_mpi_plan_many_transpose(n0, n1, 2, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                          reinterpret_cast<double*>(in.data()),
                                          reinterpret_cast<double*>(out.data()),
                                          detail::mpi_comm(comm), destroy);
    });
  };
  t.to_columns = transpose(ny, hx, t.rows, t.columns);
  t.to_rows = transpose(hx, ny, t.columns, t.rows);
  for (int sign : {FFTW_FORWARD, FFTW_BACKWARD}) {
    (sign == FFTW_FORWARD ? t.forward_y : t.inverse_y) = detail::plan_many(columns, threads, [&] {
      return fftw_plan_many_dft(1, &n2y, int(columns), t.padded_columns.data(), nullptr, 1, n2y,
                                t.padded_columns.data(), nullptr, 1, n2y, sign, flags);
    });
  }
  t.multiplier = love_spectrum(comm, grid, plane_strain_modulus, t.slab, planning, threads);
}

const Slab& DistributedDcfftOperator::slab() const {
  return t_->slab;
}

double DistributedDcfftOperator::communication_seconds() const {
  return t_->transpose_seconds;
}

void DistributedDcfftOperator::apply(const Field& pressure, Field& displacement) {
  check_pressure(pressure, displacement, "DistributedDcfftOperator");
  Transforms& t = *t_;
  const std::ptrdiff_t nx = t.slab.nx, ny = t.slab.ny, rows = t.slab.rows;
  const std::ptrdiff_t columns = t.slab.columns;
  displacement.resize(nx, rows);
  const auto timed_transpose = [&t](const FftwPlan& plan) {
    const auto start = std::chrono::steady_clock::now();
    plan.execute();
    t.transpose_seconds += detail::seconds_since(start);
  };
  // Each row, then zeros (the last inverse left its rows' second halves in the buffer).
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    double* row = t.padded.data() + 2 * nx * r;
    std::copy_n(&pressure(0, r), nx, row);
    std::fill_n(row + nx, nx, 0.0);
  }
  detail::execute_if_planned(t.r2c);
  timed_transpose(t.to_columns);
  std::complex<double>* pc = as_complex(t.padded_columns.data());
  std::complex<double>* columns_of = as_complex(t.columns.data());
  for (std::ptrdiff_t c = 0; c < columns; ++c) {
    std::copy_n(columns_of + ny * c, ny, pc + 2 * ny * c);
    std::fill_n(pc + 2 * ny * c + ny, ny, std::complex<double>(0.0));
  }
  detail::execute_if_planned(t.forward_y);
  for (std::size_t n = 0; n < t.multiplier.size(); ++n) pc[n] *= t.multiplier[n];
  detail::execute_if_planned(t.inverse_y);
  for (std::ptrdiff_t c = 0; c < columns; ++c)
    std::copy_n(pc + 2 * ny * c, ny, columns_of + ny * c);
  timed_transpose(t.to_rows);
  detail::execute_if_planned(t.c2r);
  for (std::ptrdiff_t r = 0; r < rows; ++r)
    std::copy_n(t.padded.data() + 2 * nx * r, nx, &displacement(0, r));
}

}  // namespace coatfft
