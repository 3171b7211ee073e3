#include "contact/detail/fourier_preconditioner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "convolution/kernels/g0.hpp"

namespace coatfft::detail {

FourierPreconditioner::FourierPreconditioner(const Grid& grid, int threads, Planning planning)
    : grid_(grid), nx_(grid.nx()), ny_(grid.ny()), hx_(grid.nx() / 2 + 1) {
  const auto n_real = static_cast<std::size_t>(nx_ * ny_);
  const auto n_complex = static_cast<std::size_t>(hx_ * ny_);
  real_ = FftwRealBuffer(n_real);
  spectrum_ = FftwComplexBuffer(n_complex);
  // Row-major dimensions {ny, nx}: a Field (x fastest) is a C-order (ny, nx) array.
  const int nyi = static_cast<int>(ny_);
  const int nxi = static_cast<int>(nx_);
  const unsigned flags = fftw_flags(planning);
  forward_ = FftwPlan::create(threads, [&] {
    return fftw_plan_dft_r2c_2d(nyi, nxi, real_.data(), spectrum_.data(), flags);
  });
  backward_ = FftwPlan::create(threads, [&] {
    return fftw_plan_dft_c2r_2d(nyi, nxi, spectrum_.data(), real_.data(), flags);
  });
  const double norm = 1.0 / static_cast<double>(nx_ * ny_);
  sigma_.resize(hx_, ny_);
  for (std::ptrdiff_t j = 0; j < ny_; ++j)
    for (std::ptrdiff_t i = 0; i < hx_; ++i) sigma_(i, j) = preconditioner_symbol(grid, i, j, norm);
}

double preconditioner_symbol(const Grid& grid, std::ptrdiff_t i, std::ptrdiff_t j, double norm) {
  const double dkx = 2.0 * std::numbers::pi / grid.lx();
  const double dky = 2.0 * std::numbers::pi / grid.ly();
  // Mean of 1/|k| over the central cell [-dkx/2, dkx/2] x [-dky/2, dky/2] (docs/theory.md 3.1).
  if (i == 0 && j == 0) return norm / mean_inverse_wavenumber(dkx, dky);
  const double ky = dky * static_cast<double>(j <= grid.ny() / 2 ? j : j - grid.ny());
  return std::hypot(dkx * static_cast<double>(i), ky) * norm;
}

bool FourierPreconditioner::adapt_to_kernel(const Field& kernel) {
  std::copy_n(kernel.data(), static_cast<std::size_t>(nx_ * ny_), real_.data());
  forward_.execute();
  const std::complex<double>* s = as_complex(spectrum_.data());
  const double norm = 1.0 / static_cast<double>(nx_ * ny_);
  // The factor sqrt(1 / (|k| K^)) of each mode, 1 for a half-space (up to a constant).
  Field factor(hx_, ny_);
  for (std::ptrdiff_t q = 1; q < hx_ * ny_; ++q) {
    const double k_hat = s[q].real();  // the kernel is even in both offsets: K^ is real
    if (!(k_hat > 0) || !std::isfinite(k_hat)) return false;
    factor(q) = std::sqrt(1.0 / (preconditioner_symbol(grid_, q % hx_, q / hx_, 1.0) * k_hat));
  }
  if (hx_ * ny_ == 1) return false;       // a single cell: only the mean, which |k|'s rule sets
  factor(0) = factor(ny_ > 1 ? hx_ : 1);  // mode (0, 1), else (1, 0)
  for (std::ptrdiff_t j = 0; j < ny_; ++j)
    for (std::ptrdiff_t i = 0; i < hx_; ++i)
      sigma_(i, j) = preconditioner_symbol(grid_, i, j, norm) * factor(i, j);
  return true;
}

void FourierPreconditioner::apply(Field& field) {
  const auto n_real = static_cast<std::size_t>(nx_ * ny_);
  std::copy_n(field.data(), n_real, real_.data());
  apply();
  std::copy_n(real_.data(), n_real, field.data());
}

void FourierPreconditioner::apply() {
  forward_.execute();
  std::complex<double>* s = as_complex(spectrum_.data());
  const double* sigma = sigma_.data();
  const auto n_complex = static_cast<std::size_t>(hx_ * ny_);
  for (std::size_t q = 0; q < n_complex; ++q) s[q] *= sigma[q];
  backward_.execute();
}

}  // namespace coatfft::detail
