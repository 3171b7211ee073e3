#include "convolution/dcfft_operator.hpp"

#include <algorithm>
#include <chrono>
#include <complex>

#include "core/error.hpp"

namespace coatfft {

DcfftOperator::DcfftOperator(const InfluenceKernel& kernel, Planning planning, int threads)
    : grid_(kernel.grid()),
      mx_(2 * kernel.grid().nx()),
      my_(2 * kernel.grid().ny()),
      hx_(kernel.grid().nx() + 1) {
  const auto start = std::chrono::steady_clock::now();
  COATFFT_REQUIRE(threads >= 1, "DcfftOperator: threads = ", threads, ", but must be >= 1");
  const auto n_real = static_cast<std::size_t>(mx_ * my_);
  const auto n_complex = static_cast<std::size_t>(hx_ * my_);
  real_ = FftwRealBuffer(n_real);
  spectrum_ = FftwComplexBuffer(n_complex);
  kernel_hat_ = FftwComplexBuffer(n_complex);
  // Row-major dimensions {my, mx}: a Field (x fastest) is a C-order (ny, nx) array.
  const int nmy = static_cast<int>(my_);
  const int nmx = static_cast<int>(mx_);
  const unsigned flags = fftw_flags(planning);
  forward_ = FftwPlan::create(threads, [&] {
    return fftw_plan_dft_r2c_2d(nmy, nmx, real_.data(), spectrum_.data(), flags);
  });
  backward_ = FftwPlan::create(threads, [&] {
    return fftw_plan_dft_c2r_2d(nmy, nmx, spectrum_.data(), real_.data(), flags);
  });
  // Kernel spectrum, once, with FFTW's unnormalised inverse compensated by 1/(mx my).
  const Field& w = kernel.wrapped();
  std::copy_n(w.data(), n_real, real_.data());
  forward_.execute();
  const double scale = 1.0 / static_cast<double>(mx_ * my_);
  const std::complex<double>* s = as_complex(spectrum_.data());
  std::complex<double>* k = as_complex(kernel_hat_.data());
  for (std::size_t q = 0; q < n_complex; ++q) k[q] = s[q] * scale;
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void DcfftOperator::apply(const Field& pressure, Field& displacement) {
  const std::ptrdiff_t nx = grid_.nx();
  const std::ptrdiff_t ny = grid_.ny();
  COATFFT_REQUIRE(pressure.rows() == nx && pressure.cols() == ny,
                  "DcfftOperator::apply: pressure has shape (", pressure.rows(), ", ",
                  pressure.cols(), "), but the grid needs (", nx, ", ", ny, ")");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "DcfftOperator::apply: displacement must not alias pressure");
  double* r = real_.data();
  std::fill_n(r, static_cast<std::size_t>(mx_ * my_), 0.0);
  for (std::ptrdiff_t j = 0; j < ny; ++j) std::copy_n(&pressure(0, j), nx, r + j * mx_);
  forward_.execute();
  std::complex<double>* s = as_complex(spectrum_.data());
  const std::complex<double>* k = as_complex(kernel_hat_.data());
  const auto n_complex = static_cast<std::size_t>(hx_ * my_);
  for (std::size_t q = 0; q < n_complex; ++q) s[q] *= k[q];
  backward_.execute();
  displacement.resize(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j) std::copy_n(r + j * mx_, nx, &displacement(0, j));
}

}  // namespace coatfft
