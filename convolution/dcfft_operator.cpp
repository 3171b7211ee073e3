#include "convolution/dcfft_operator.hpp"

#include <algorithm>
#include <chrono>
#include <complex>
#include <thread>

#include "core/error.hpp"

namespace coatfft {
namespace {

// Bytes of one worker's block of y transforms: small enough to stay in L2 while it is gathered,
// transformed forward, filtered, transformed back and scattered (one pass over main memory).
// 32-256 KiB measured alike at 1024^2 and 2048^2; 128 KiB and more lost ~20% at 256^2.
constexpr std::ptrdiff_t block_bytes = 64 * 1024;

// True when K(di, dj) = K(-di, dj) = K(di, -dj) exactly; then the DFT of the wrapped array is
// real and even, and equals a 2-D DCT-I of its (nx + 1) x (ny + 1) corner.
bool is_even(const Field& w, std::ptrdiff_t nx, std::ptrdiff_t ny) {
  const std::ptrdiff_t mx = 2 * nx;
  const std::ptrdiff_t my = 2 * ny;
  for (std::ptrdiff_t j = 0; j < my; ++j)
    for (std::ptrdiff_t i = 1; i < nx; ++i)
      if (w(i, j) != w(mx - i, j)) return false;
  for (std::ptrdiff_t j = 1; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < mx; ++i)
      if (w(i, j) != w(i, my - j)) return false;
  return true;
}

}  // namespace

DcfftOperator::DcfftOperator(const Grid& grid, Planning planning, int threads)
    : grid_(grid),
      nx_(grid.nx()),
      ny_(grid.ny()),
      mx_(2 * grid.nx()),
      my_(2 * grid.ny()),
      hx_(grid.nx() + 1),
      threads_(threads) {
  const auto start = std::chrono::steady_clock::now();
  COATFFT_REQUIRE(threads >= 1, "DcfftOperator: threads = ", threads, ", but must be >= 1");
  const unsigned flags = fftw_flags(planning);

  // x transforms of the ny data rows only (the padding rows ny..2ny-1 are zero on input and
  // not needed on output), in place: real rows of stride 2 hx, complex rows of stride hx.
  rows_ = FftwComplexBuffer(static_cast<std::size_t>(ny_ * hx_));
  double* real = reinterpret_cast<double*>(rows_.data());
  const int n_x[1] = {static_cast<int>(mx_)};
  const int ny = static_cast<int>(ny_);
  const int hx = static_cast<int>(hx_);
  forward_x_ = FftwPlan::create(threads, [&] {
    return fftw_plan_many_dft_r2c(1, n_x, ny, real, nullptr, 1, 2 * hx, rows_.data(), nullptr, 1,
                                  hx, flags);
  });
  backward_x_ = FftwPlan::create(threads, [&] {
    return fftw_plan_many_dft_c2r(1, n_x, ny, rows_.data(), nullptr, 1, hx, real, nullptr, 1,
                                  2 * hx, flags);
  });

  // y transforms (length 2ny) of the hx spectrum columns, by blocks of block_ columns.
  block_ = std::clamp<std::ptrdiff_t>(block_bytes / (my_ * 16), 1, hx_);
  nb_blocks_ = (hx_ + block_ - 1) / block_;
  const auto nb_workers = static_cast<std::size_t>(std::min<std::ptrdiff_t>(threads, nb_blocks_));
  const int n_y[1] = {static_cast<int>(my_)};
  const int bw = static_cast<int>(block_);
  workers_.resize(nb_workers);
  for (Worker& w : workers_) {
    w.block = FftwComplexBuffer(static_cast<std::size_t>(my_ * block_));
    for (auto [plan, sign] :
         {std::pair{&w.forward_y, FFTW_FORWARD}, {&w.backward_y, FFTW_BACKWARD}})
      *plan = FftwPlan::create(1, [&] {
        return fftw_plan_many_dft(1, n_y, bw, w.block.data(), nullptr, 1, 2 * ny, w.block.data(),
                                  nullptr, 1, 2 * ny, sign, flags);
      });
  }

  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

DcfftOperator::DcfftOperator(const InfluenceKernel& kernel, Planning planning, int threads)
    : DcfftOperator(kernel.grid(), planning, threads) {
  const auto start = std::chrono::steady_clock::now();
  const Field& wrapped = kernel.wrapped();
  even_ = is_even(wrapped, nx_, ny_);
  if (even_) {
    compute_even_spectrum(wrapped.data(), mx_);
  } else {
    compute_general_spectrum(wrapped);
  }
  setup_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

DcfftOperator::DcfftOperator(const EvenInfluenceKernel& kernel, Planning planning, int threads)
    : DcfftOperator(kernel.grid, planning, threads) {
  const auto start = std::chrono::steady_clock::now();
  const Field& q = kernel.quarter;
  COATFFT_REQUIRE(q.rows() == hx_ && q.cols() == ny_ + 1,
                  "DcfftOperator: the kernel quarter has shape (", q.rows(), ", ", q.cols(),
                  "), but the grid needs (", hx_, ", ", ny_ + 1, ")");
  COATFFT_REQUIRE(q.allFinite(), "DcfftOperator: the kernel quarter is not finite");
  even_ = true;
  compute_even_spectrum(q.data(), hx_);
  setup_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

DcfftOperator::DcfftOperator(const EvenKernelSpectrum& spectrum, Planning planning, int threads)
    : DcfftOperator(spectrum.grid, planning, threads) {
  const auto start = std::chrono::steady_clock::now();
  const Field& s = spectrum.values;
  COATFFT_REQUIRE(s.rows() == hx_ && s.cols() == ny_ + 1,
                  "DcfftOperator: the kernel spectrum has shape (", s.rows(), ", ", s.cols(),
                  "), but the grid needs (", hx_, ", ", ny_ + 1, ")");
  COATFFT_REQUIRE(s.allFinite(), "DcfftOperator: the kernel spectrum is not finite");
  even_ = true;
  // Stored transposed ([kx][ky], the blocks' layout) with FFTW's 1/(mx my) folded in, as
  // compute_even_spectrum leaves it.
  const std::ptrdiff_t len = ny_ + 1;
  kernel_even_ = FftwRealBuffer(static_cast<std::size_t>(hx_ * len));
  double* k = kernel_even_.data();
  const double scale = 1.0 / static_cast<double>(mx_ * my_);
  for (std::ptrdiff_t jy = 0; jy < len; ++jy)
    for (std::ptrdiff_t jx = 0; jx < hx_; ++jx) k[jx * len + jy] = scale * s(jx, jy);
  setup_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void DcfftOperator::compute_even_spectrum(const double* corner, std::ptrdiff_t column_stride) {
  // DFT of the 2n-periodic even sequence = DCT-I (FFTW REDFT00) of its first n + 1 entries; the
  // slots nx, ny hold the wrap-around layout's zeros (whatever they hold, those offsets never
  // reach the cropped output). Stored column-major, [kx][ky], like the blocks it multiplies. The
  // transform reads the (nx + 1) x (ny + 1) corner (x fastest; of the wrapped array or of an
  // EvenInfluenceKernel's quarter) in place through guru strides and writes the transposed layout
  // directly, so FFTW's tiled copies do the transposition (a separate strided copy loop cost
  // about as much as the transform at 1024^2). FFTW_PRESERVE_INPUT (the default for out-of-place
  // r2r anyway, FFTW manual 4.3.2) keeps the input read-only. One-off: FFTW_ESTIMATE, which
  // plans without touching the arrays.
  const std::ptrdiff_t len = ny_ + 1;
  kernel_even_ = FftwRealBuffer(static_cast<std::size_t>(hx_ * len));
  double* k = kernel_even_.data();
  const fftw_iodim dims[2] = {{static_cast<int>(hx_), 1, static_cast<int>(len)},
                              {static_cast<int>(len), static_cast<int>(column_stride), 1}};
  const fftw_r2r_kind kinds[2] = {FFTW_REDFT00, FFTW_REDFT00};
  double* in = const_cast<double*>(corner);
  const FftwPlan dct = FftwPlan::create(threads_, [&] {
    return fftw_plan_guru_r2r(2, dims, 0, nullptr, in, k, kinds,
                              FFTW_ESTIMATE | FFTW_PRESERVE_INPUT);
  });
  dct.execute();
  const double scale = 1.0 / static_cast<double>(mx_ * my_);
  std::for_each(k, k + hx_ * len, [scale](double& v) { v *= scale; });
}

void DcfftOperator::compute_general_spectrum(const Field& wrapped) {
  // Column-major [kx][ky] half spectrum, built without a second full-size array: r2c of each of
  // the 2ny rows through a one-row buffer, scattered into the columns, then the y transforms in
  // place. One-off: FFTW_ESTIMATE.
  kernel_general_ = FftwComplexBuffer(static_cast<std::size_t>(hx_ * my_));
  std::complex<double>* k = as_complex(kernel_general_.data());
  FftwRealBuffer row(static_cast<std::size_t>(mx_));
  FftwComplexBuffer row_hat(static_cast<std::size_t>(hx_));
  const FftwPlan r2c = FftwPlan::create(1, [&] {
    return fftw_plan_dft_r2c_1d(static_cast<int>(mx_), row.data(), row_hat.data(), FFTW_ESTIMATE);
  });
  const int n_y[1] = {static_cast<int>(my_)};
  const FftwPlan dft_y = FftwPlan::create(threads_, [&] {
    return fftw_plan_many_dft(1, n_y, static_cast<int>(hx_), kernel_general_.data(), nullptr, 1,
                              static_cast<int>(my_), kernel_general_.data(), nullptr, 1,
                              static_cast<int>(my_), FFTW_FORWARD, FFTW_ESTIMATE);
  });
  const std::complex<double>* h = as_complex(row_hat.data());
  for (std::ptrdiff_t j = 0; j < my_; ++j) {
    std::copy_n(&wrapped(0, j), mx_, row.data());
    r2c.execute();
    for (std::ptrdiff_t kx = 0; kx < hx_; ++kx) k[kx * my_ + j] = h[kx];
  }
  dft_y.execute();
  const double scale = 1.0 / static_cast<double>(mx_ * my_);
  std::for_each(k, k + hx_ * my_, [scale](std::complex<double>& v) { v *= scale; });
}

void DcfftOperator::convolve_columns(Worker& worker, std::ptrdiff_t first_block,
                                     std::ptrdiff_t end_block) {
  std::complex<double>* rows = as_complex(rows_.data());
  std::complex<double>* t = as_complex(worker.block.data());
  const std::ptrdiff_t bw = block_;
  const std::ptrdiff_t my = my_;
  const std::ptrdiff_t ny = ny_;
  const std::complex<double> zero(0.0, 0.0);
  for (std::ptrdiff_t b = first_block; b < end_block; ++b) {
    const std::ptrdiff_t c0 = b * bw;
    const std::ptrdiff_t width = std::min(bw, hx_ - c0);
    // Gather (transpose) the ny data rows of these columns into contiguous columns of length
    // 2ny, whose second half is the zero padding in y: stride-1 y transforms are ~30% faster
    // than strided ones, and the block stays in cache from gather to scatter.
    for (std::ptrdiff_t ky = 0; ky < ny; ++ky) {
      const std::complex<double>* src = rows + ky * hx_ + c0;
      for (std::ptrdiff_t c = 0; c < width; ++c) t[c * my + ky] = src[c];
    }
    for (std::ptrdiff_t c = 0; c < bw; ++c) {
      std::fill(t + c * my + (c < width ? ny : 0), t + (c + 1) * my, zero);
    }
    worker.forward_y.execute();
    for (std::ptrdiff_t c = 0; c < width; ++c) {
      std::complex<double>* col = t + c * my;
      if (even_) {
        // Real, even spectrum: rows ky > ny mirror 2ny - ky.
        const double* k = kernel_even_.data() + (c0 + c) * (ny + 1);
        for (std::ptrdiff_t ky = 0; ky <= ny; ++ky) col[ky] *= k[ky];
        for (std::ptrdiff_t ky = ny + 1; ky < my; ++ky) col[ky] *= k[my - ky];
      } else {
        const std::complex<double>* k = as_complex(kernel_general_.data()) + (c0 + c) * my;
        for (std::ptrdiff_t ky = 0; ky < my; ++ky) col[ky] *= k[ky];
      }
    }
    worker.backward_y.execute();
    // Only the rows ky < ny of the inverse are inside the crop.
    for (std::ptrdiff_t ky = 0; ky < ny; ++ky) {
      std::complex<double>* dst = rows + ky * hx_ + c0;
      for (std::ptrdiff_t c = 0; c < width; ++c) dst[c] = t[c * my + ky];
    }
  }
}

void DcfftOperator::apply(const Field& pressure, Field& displacement) {
  COATFFT_REQUIRE(pressure.rows() == nx_ && pressure.cols() == ny_,
                  "DcfftOperator::apply: pressure has shape (", pressure.rows(), ", ",
                  pressure.cols(), "), but the grid needs (", nx_, ", ", ny_, ")");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "DcfftOperator::apply: displacement must not alias pressure");
  double* real = reinterpret_cast<double*>(rows_.data());
  const std::ptrdiff_t stride = 2 * hx_;
  for (std::ptrdiff_t j = 0; j < ny_; ++j) {
    double* row = real + j * stride;
    std::copy_n(&pressure(0, j), nx_, row);
    std::fill(row + nx_, row + stride, 0.0);
  }
  forward_x_.execute();
  const auto nb_workers = static_cast<std::ptrdiff_t>(workers_.size());
  if (nb_workers == 1) {
    convolve_columns(workers_[0], 0, nb_blocks_);
  } else {
    std::vector<std::jthread> pool;
    pool.reserve(static_cast<std::size_t>(nb_workers - 1));
    for (std::ptrdiff_t w = 1; w < nb_workers; ++w)
      pool.emplace_back([this, w, nb_workers] {
        convolve_columns(workers_[static_cast<std::size_t>(w)], nb_blocks_ * w / nb_workers,
                         nb_blocks_ * (w + 1) / nb_workers);
      });
    convolve_columns(workers_[0], 0, nb_blocks_ / nb_workers);
  }
  backward_x_.execute();
  displacement.resize(nx_, ny_);
  for (std::ptrdiff_t j = 0; j < ny_; ++j) std::copy_n(real + j * stride, nx_, &displacement(0, j));
}

}  // namespace coatfft
