#include "convolution/operators/detail/dcfft_operator.hpp"

#include <algorithm>
#include <chrono>
#include <complex>

#include "convolution/kernels/detail/coarse_kernel.hpp"
#include "core/detail/fft_size.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

// Bytes of one worker's block of y transforms: small enough to stay in L2 while it is gathered,
// transformed forward, filtered, transformed back and scattered (one pass over main memory).
// 32-256 KiB measured alike at 1024^2 and 2048^2; 128 KiB and more lost ~20% at 256^2.
constexpr std::ptrdiff_t block_bytes = 64 * 1024;

}  // namespace

std::ptrdiff_t DcfftOperator::padded_size(std::ptrdiff_t n, InfluenceKernel::Form form) {
  COATFFT_REQUIRE(n >= 1, "DcfftOperator::padded_size: n = ", n, ", but must be >= 1");
  // A sampled spectrum exists on its own lattice only; coefficients wrap exactly on any period
  // M >= 2n - 1 (offsets -(n - 1)..n - 1 do not overlap), of which the fastest even one is taken.
  if (form == InfluenceKernel::Form::spectrum) return 2 * n;
  return detail::fast_even_fft_size(2 * n - 1);
}

DcfftOperator::DcfftOperator(const InfluenceKernel& kernel, Planning planning, int threads)
    : grid_(kernel.grid()),
      nx_(grid_.nx()),
      ny_(grid_.ny()),
      mx_(padded_size(grid_.nx(), kernel.form())),
      my_(padded_size(grid_.ny(), kernel.form())),
      hx_(mx_ / 2 + 1),
      hy_(my_ / 2),
      threads_(threads),
      method_(kernel.method()) {
  const auto start = std::chrono::steady_clock::now();
  COATFFT_REQUIRE(threads >= 1, "DcfftOperator: threads = ", threads, ", but must be >= 1");
  plan_transforms(planning);
  if (kernel.form() == InfluenceKernel::Form::coefficients)
    transform_coefficients(kernel.quarter());
  else
    store_spectrum(kernel.quarter());
  setup_seconds_ = detail::seconds_since(start);
}

void DcfftOperator::plan_transforms(Planning planning) {
  const int threads = threads_;
  const unsigned flags = fftw_flags(planning);

  // x transforms of the ny data rows only (the padding rows ny..my-1 are zero on input and
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

  // y transforms (length my) of the hx spectrum columns, by blocks of block_ columns.
  block_ = std::clamp<std::ptrdiff_t>(block_bytes / (my_ * 16), 1, hx_);
  nb_blocks_ = (hx_ + block_ - 1) / block_;
  const auto nb_workers = static_cast<std::size_t>(std::min<std::ptrdiff_t>(threads, nb_blocks_));
  const int my = static_cast<int>(my_);
  const int n_y[1] = {my};
  const int bw = static_cast<int>(block_);
  workers_.resize(nb_workers);
  for (Worker& w : workers_) {
    w.block = FftwComplexBuffer(static_cast<std::size_t>(my_ * block_));
    for (auto [plan, sign] :
         {std::pair{&w.forward_y, FFTW_FORWARD}, {&w.backward_y, FFTW_BACKWARD}})
      *plan = FftwPlan::create(1, [&, sign = sign] {  // clang 14 cannot capture a binding
        return fftw_plan_many_dft(1, n_y, bw, w.block.data(), nullptr, 1, my, w.block.data(),
                                  nullptr, 1, my, sign, flags);
      });
  }
}

void DcfftOperator::store_spectrum(const Field& s) {
  // Stored transposed ([kx][ky], the blocks' layout) with FFTW's 1/(mx my) folded in, as
  // transform_coefficients leaves it. The spectrum form pads to exactly (2nx, 2ny), so the
  // quarter is (hx, hy + 1).
  const std::ptrdiff_t len = hy_ + 1;
  kernel_spectrum_ = FftwRealBuffer(static_cast<std::size_t>(hx_ * len));
  double* k = kernel_spectrum_.data();
  const double scale = 1.0 / static_cast<double>(mx_ * my_);
  for (std::ptrdiff_t jy = 0; jy < len; ++jy)
    for (std::ptrdiff_t jx = 0; jx < hx_; ++jx) k[jx * len + jy] = scale * s(jx, jy);
}

void DcfftOperator::transform_coefficients(const Field& quarter) {
  // DFT of the M-periodic even sequence (M even) = DCT-I (FFTW REDFT00) of its first M/2 + 1
  // entries: the offsets 0..n - 1, then zeros (the slot n of the quarter is one of them; whatever
  // the slots n..M/2 held, those offsets never reach the cropped output). Stored column-major,
  // [kx][ky], like the blocks it multiplies. The transform reads the (hx, hy + 1) quarter (x
  // fastest) in place through guru strides and writes the transposed layout directly, so FFTW's
  // tiled copies do the transposition (a separate strided copy loop cost about as much as the
  // transform at 1024^2). FFTW_PRESERVE_INPUT (the default for out-of-place r2r anyway, FFTW
  // manual 4.3.2) keeps the input read-only. One-off: FFTW_ESTIMATE, which plans without
  // touching the arrays.
  const std::ptrdiff_t len = hy_ + 1;
  kernel_spectrum_ = FftwRealBuffer(static_cast<std::size_t>(hx_ * len));
  double* k = kernel_spectrum_.data();
  const fftw_iodim dims[2] = {{static_cast<int>(hx_), 1, static_cast<int>(len)},
                              {static_cast<int>(len), static_cast<int>(hx_), 1}};
  const fftw_r2r_kind kinds[2] = {FFTW_REDFT00, FFTW_REDFT00};
  // Padded past 2n: the quarter grows to (hx, hy + 1) with zeros (a contiguous copy, cheap).
  // At M = 2n, the usual case for 7-smooth n, the kernel's quarter is read as it is.
  Field padded;
  if (hx_ != nx_ + 1 || len != ny_ + 1) {
    padded = Field::Zero(hx_, len);
    padded.topLeftCorner(nx_, ny_) = quarter.topLeftCorner(nx_, ny_);
  }
  double* in = const_cast<double*>(padded.size() > 0 ? padded.data() : quarter.data());
  const FftwPlan dct = FftwPlan::create(threads_, [&] {
    return fftw_plan_guru_r2r(2, dims, 0, nullptr, in, k, kinds,
                              FFTW_ESTIMATE | FFTW_PRESERVE_INPUT);
  });
  dct.execute();
  const double scale = 1.0 / static_cast<double>(mx_ * my_);
  std::for_each(k, k + hx_ * len, [scale](double& v) { v *= scale; });
}

void DcfftOperator::convolve_columns(Worker& worker, std::ptrdiff_t first_block,
                                     std::ptrdiff_t end_block) {
  std::complex<double>* rows = as_complex(rows_.data());
  std::complex<double>* t = as_complex(worker.block.data());
  const std::ptrdiff_t bw = block_;
  const std::ptrdiff_t my = my_;
  const std::ptrdiff_t ny = ny_;
  const std::ptrdiff_t hy = hy_;
  const std::complex<double> zero(0.0, 0.0);
  for (std::ptrdiff_t b = first_block; b < end_block; ++b) {
    const std::ptrdiff_t c0 = b * bw;
    const std::ptrdiff_t width = std::min(bw, hx_ - c0);
    // Gather (transpose) the ny data rows of these columns into contiguous columns of length
    // my, whose rows ny..my-1 are the zero padding in y: stride-1 y transforms are ~30% faster
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
      // Real, even spectrum: rows ky > my/2 mirror my - ky.
      const double* k = kernel_spectrum_.data() + (c0 + c) * (hy + 1);
      for (std::ptrdiff_t ky = 0; ky <= hy; ++ky) col[ky] *= k[ky];
      for (std::ptrdiff_t ky = hy + 1; ky < my; ++ky) col[ky] *= k[my - ky];
    }
    worker.backward_y.execute();
    // Only the rows ky < ny of the inverse are inside the crop.
    for (std::ptrdiff_t ky = 0; ky < ny; ++ky) {
      std::complex<double>* dst = rows + ky * hx_ + c0;
      for (std::ptrdiff_t c = 0; c < width; ++c) dst[c] = t[c * my + ky];
    }
  }
}

std::unique_ptr<SurfaceOperator> DcfftOperator::coarsened() {
  if (nx_ % 2 != 0 || ny_ % 2 != 0) return nullptr;
  // The unit response is the coefficient quarter K(i, j), i, j >= 0.
  Field quarter = Field::Zero(nx_ + 1, ny_ + 1);
  quarter.topLeftCorner(nx_, ny_) = unit_response();
  const Grid coarse(nx_ / 2, ny_ / 2, grid_.lx(), grid_.ly());
  const InfluenceKernel kernel(coarse, InfluenceKernel::Form::coefficients,
                               detail::coarse_kernel_quarter(quarter), method_);
  return std::make_unique<DcfftOperator>(kernel, Planning::estimate, threads_);
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
  // One contiguous run of column blocks per worker, each with its own scratch.
  detail::parallel_chunks(0, nb_blocks_, static_cast<int>(workers_.size()),
                          [this](std::ptrdiff_t w, std::ptrdiff_t first, std::ptrdiff_t last) {
                            convolve_columns(workers_[static_cast<std::size_t>(w)], first, last);
                          });
  backward_x_.execute();
  displacement.resize(nx_, ny_);
  for (std::ptrdiff_t j = 0; j < ny_; ++j) std::copy_n(real + j * stride, nx_, &displacement(0, j));
}

}  // namespace coatfft
