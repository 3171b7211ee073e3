#include "distributed/distributed_dcfft_operator.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/error.hpp"
#include "distributed/detail/distributed_split_kernel.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "distributed/detail/slab_fft.hpp"

namespace coatfft {

// The layout of the serial DcfftOperator's pruned transform (convolution/operators/
// dcfft_operator.cpp) on slabs: the rows' half spectra in place, the columns in cache-sized
// blocks padded to 2ny, the coefficients' real spectrum on its quarter.
struct DistributedDcfftOperator::Transforms {
  Slab slab;                        // the grid's rows; columns of the (nx + 1)-entry half spectrum
  FftwComplexBuffer rows, columns;  // rows x (nx + 1), each row's 2nx reals in place; columns x ny
  FftwComplexBuffer block;          // block_columns x 2ny: columns padded for their transforms
  std::ptrdiff_t block_columns = 0;
  std::vector<double> multiplier;  // columns x (ny + 1): the spectrum / (4 nx ny) for ky <= ny
  FftwPlan r2c, c2r, to_columns, to_rows, forward_y, inverse_y;
  double transpose_seconds = 0.0;
};

namespace {

// Columns of a block: 256 KiB of padded columns (as the serial operator's blocks), so that a block
// stays in cache from its gather to its scatter.
constexpr std::ptrdiff_t block_bytes = 256 * 1024;

std::size_t entries(std::ptrdiff_t n) {
  return static_cast<std::size_t>(std::max<std::ptrdiff_t>(n, 1));
}

// This rank's rows j of Love's quarter K(i, j), 0 <= i, j <= n (his coefficients over E*, 0 in the
// slots nx and ny), x fastest: the first n + 1 entries of the (2nx, 2ny) wrap-around array, which
// is even in both offsets.
void love_quarter_rows(const Grid& g, double e_star, std::ptrdiff_t y0, std::ptrdiff_t rows,
                       int threads, double* out) {
  const std::ptrdiff_t nx = g.nx(), qx = nx + 1;
  detail::parallel_for(0, rows, threads, [&](std::ptrdiff_t r) {
    double* row = out + r * qx;
    std::fill_n(row, qx, 0.0);
    if (y0 + r >= g.ny()) return;
    detail::love_influence_row(static_cast<double>(y0 + r) * g.dy(), g.dx(), g.dy(), nx, row);
    for (std::ptrdiff_t i = 0; i < nx; ++i) row[i] /= e_star;
  });
}

// The DFT of the even (2nx, 2ny) wrap-around array is the 2-D DCT-I (FFTW's REDFT00) of its
// quarter, as in DcfftOperator::transform_coefficients: here on the quarter's rows (written by
// `quarter_rows(y0, rows, out)`, collectively), FFTW-MPI's transpose, then its columns, which are
// the operator's (FFTW-MPI splits nx + 1 columns alike for any count of rows; checked). Returns
// this rank's columns x (ny + 1), over 4 nx ny.
std::vector<double> coefficient_spectrum(
    const Communicator& comm, const Grid& g, const Slab& slab, int threads,
    const DistributedDcfftOperator::QuarterRowsFunction& quarter_rows) {
  const std::ptrdiff_t qx = g.nx() + 1, qy = g.ny() + 1;
  const std::ptrdiff_t n[2] = {qy, qx};
  std::ptrdiff_t rows = 0, y0 = 0, columns = 0, kx0 = 0;
  const std::ptrdiff_t doubles =
      fftw_mpi_local_size_many_transposed(2, n, 1, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                          detail::mpi_comm(comm), &rows, &y0, &columns, &kx0);
  COATFFT_REQUIRE(columns == slab.columns && (columns == 0 || kx0 == slab.kx0),
                  "DistributedDcfftOperator: FFTW-MPI split the quarter's columns otherwise");
  // The transpose's second array after the rows: the split kernel's own arrays are freed by then.
  FftwRealBuffer quarter(entries(doubles));
  quarter_rows(y0, rows, quarter.data());
  FftwRealBuffer transposed(entries(doubles));
  detail::dct1_rows_then_columns(comm, qy, qx, rows, columns, quarter.data(), transposed.data(),
                                 threads);
  const double norm = 1.0 / static_cast<double>(4 * g.nx() * g.ny());
  std::vector<double> m(static_cast<std::size_t>(columns * qy));
  for (std::size_t k = 0; k < m.size(); ++k) m[k] = norm * transposed.data()[k];
  return m;
}

}  // namespace

DistributedDcfftOperator::~DistributedDcfftOperator() = default;

namespace {

double checked_modulus(double e_star) {
  COATFFT_REQUIRE(std::isfinite(e_star) && e_star > 0, "DistributedDcfftOperator: E* = ", e_star,
                  " Pa, but it must be finite and > 0");
  return e_star;
}

}  // namespace

DistributedDcfftOperator::DistributedDcfftOperator(const Communicator& comm, const Grid& grid,
                                                   double plane_strain_modulus, Planning planning,
                                                   int threads)
    : DistributedDcfftOperator(comm, grid, Method::dcfft, planning, threads,
                               [&grid, e_star = checked_modulus(plane_strain_modulus), threads](
                                   std::ptrdiff_t y0, std::ptrdiff_t rows, double* out) {
                                 love_quarter_rows(grid, e_star, y0, rows, threads, out);
                               }) {}

DistributedDcfftOperator::DistributedDcfftOperator(const Communicator& comm, const Grid& grid,
                                                   const Frf& frf,
                                                   const SplitKernelOptions& options,
                                                   Planning planning, int threads,
                                                   SplitKernelReport* report)
    : DistributedDcfftOperator(comm, grid, Method::frf_split, planning, threads,
                               [&](std::ptrdiff_t y0, std::ptrdiff_t rows, double* out) {
                                 detail::split_quarter_rows(comm, grid, frf, options, y0, rows, out,
                                                            report);
                               }) {}

DistributedDcfftOperator::DistributedDcfftOperator(const Communicator& comm, const Grid& grid,
                                                   Method method, Planning planning, int threads,
                                                   const QuarterRowsFunction& quarter_rows)
    : DistributedOperator(comm, grid), method_(method), t_(std::make_unique<Transforms>()) {
  COATFFT_REQUIRE(threads >= 1, "DistributedDcfftOperator: threads = ", threads, " must be >= 1");
  Transforms& t = *t_;
  const std::ptrdiff_t nx = grid.nx(), ny = grid.ny(), hx = nx + 1;
  // The half spectrum of a padded row has nx + 1 entries: the slabs of a (2nx, ny) grid.
  std::ptrdiff_t doubles = 0;
  t.slab = detail::slab_of(comm, 2 * nx, ny, doubles);
  t.slab.nx = nx;
  // The coefficients first: their construction's arrays are freed before the transforms' are made.
  t.multiplier = coefficient_spectrum(comm, grid, t.slab, threads, quarter_rows);
  const std::ptrdiff_t rows = t.slab.rows, columns = t.slab.columns;
  t.rows = FftwComplexBuffer(entries(doubles / 2));
  t.columns = FftwComplexBuffer(entries(doubles / 2));
  t.block_columns =
      std::clamp<std::ptrdiff_t>(block_bytes / (32 * ny), 1, std::max(columns, std::ptrdiff_t{1}));
  t.block = FftwComplexBuffer(entries(2 * ny * t.block_columns));
  const unsigned flags = fftw_flags(planning);
  const int n2x = static_cast<int>(2 * nx), n2y = static_cast<int>(2 * ny), h = int(hx);
  double* real_rows = reinterpret_cast<double*>(t.rows.data());
  t.r2c = detail::plan_many(rows, threads, [&] {
    return fftw_plan_many_dft_r2c(1, &n2x, int(rows), real_rows, nullptr, 1, 2 * h, t.rows.data(),
                                  nullptr, 1, h, flags);
  });
  t.c2r = detail::plan_many(rows, threads, [&] {
    return fftw_plan_many_dft_c2r(1, &n2x, int(rows), t.rows.data(), nullptr, 1, h, real_rows,
                                  nullptr, 1, 2 * h, flags);
  });
  // Out of place, with FFTW_DESTROY_INPUT: each transpose's input is rewritten before its next use.
  const auto transpose = [&](std::ptrdiff_t n0, std::ptrdiff_t n1, FftwComplexBuffer& in,
                             FftwComplexBuffer& out) {
    return FftwPlan::create(threads, [&] {
      return fftw_mpi_plan_many_transpose(n0, n1, 2, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                          reinterpret_cast<double*>(in.data()),
                                          reinterpret_cast<double*>(out.data()),
                                          detail::mpi_comm(comm), flags | FFTW_DESTROY_INPUT);
    });
  };
  t.to_columns = transpose(ny, hx, t.rows, t.columns);
  t.to_rows = transpose(hx, ny, t.columns, t.rows);
  for (int sign : {FFTW_FORWARD, FFTW_BACKWARD}) {
    (sign == FFTW_FORWARD ? t.forward_y : t.inverse_y) = detail::plan_many(columns, 1, [&] {
      return fftw_plan_many_dft(1, &n2y, int(t.block_columns), t.block.data(), nullptr, 1, n2y,
                                t.block.data(), nullptr, 1, n2y, sign, flags);
    });
  }
}

const Slab& DistributedDcfftOperator::slab() const {
  return t_->slab;
}

double DistributedDcfftOperator::communication_seconds() const {
  return t_->transpose_seconds;
}

// Each block of this rank's columns: gathered with its zero padding to 2ny, transformed,
// multiplied by the real, even spectrum (ky > ny mirrors 2ny - ky), transformed back, and its first
// ny entries scattered back: the entries ny..2ny - 1 are outside the crop.
void DistributedDcfftOperator::convolve_columns() {
  Transforms& t = *t_;
  const std::ptrdiff_t ny = t.slab.ny, columns = t.slab.columns, bw = t.block_columns;
  std::complex<double>* block = as_complex(t.block.data());
  std::complex<double>* cols = as_complex(t.columns.data());
  for (std::ptrdiff_t c0 = 0; c0 < columns; c0 += bw) {
    const std::ptrdiff_t width = std::min(bw, columns - c0);
    std::fill_n(block, 2 * ny * bw, std::complex<double>(0.0));
    for (std::ptrdiff_t c = 0; c < width; ++c)
      std::copy_n(cols + (c0 + c) * ny, ny, block + 2 * ny * c);
    t.forward_y.execute();
    for (std::ptrdiff_t c = 0; c < width; ++c) {
      std::complex<double>* col = block + 2 * ny * c;
      const double* k = t.multiplier.data() + (c0 + c) * (ny + 1);
      for (std::ptrdiff_t ky = 0; ky <= ny; ++ky) col[ky] *= k[ky];
      for (std::ptrdiff_t ky = ny + 1; ky < 2 * ny; ++ky) col[ky] *= k[2 * ny - ky];
    }
    t.inverse_y.execute();
    for (std::ptrdiff_t c = 0; c < width; ++c)
      std::copy_n(block + 2 * ny * c, ny, cols + (c0 + c) * ny);
  }
}

void DistributedDcfftOperator::apply(const Field& pressure, Field& displacement) {
  check_pressure(pressure, displacement, "DistributedDcfftOperator");
  Transforms& t = *t_;
  const std::ptrdiff_t nx = t.slab.nx, rows = t.slab.rows, stride = 2 * (nx + 1);
  displacement.resize(nx, rows);
  // Each row's nx values, then its zeros, in place of its half spectrum.
  double* real_rows = reinterpret_cast<double*>(t.rows.data());
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    std::copy_n(&pressure(0, r), nx, real_rows + stride * r);
    std::fill_n(real_rows + stride * r + nx, stride - nx, 0.0);
  }
  detail::execute_if_planned(t.r2c);
  detail::execute_timed(t.to_columns, t.transpose_seconds);
  convolve_columns();
  detail::execute_timed(t.to_rows, t.transpose_seconds);
  detail::execute_if_planned(t.c2r);
  for (std::ptrdiff_t r = 0; r < rows; ++r)
    std::copy_n(real_rows + stride * r, nx, &displacement(0, r));
}

}  // namespace coatfft
