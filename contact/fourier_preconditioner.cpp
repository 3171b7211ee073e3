#include "contact/detail/fourier_preconditioner.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "convolution/kernels/g0.hpp"

namespace coatfft::detail {

FourierPreconditioner::FourierPreconditioner(const Grid& grid, int threads, Planning planning)
    : FourierPreconditioner(
          SpectralFilter::create(grid, planning, Precision::double_precision, threads)) {}

FourierPreconditioner::FourierPreconditioner(std::shared_ptr<SpectralFilter> filter)
    : grid_(filter->grid()), filter_(std::move(filter)), sigma_(grid_.nx(), grid_.ny()) {
  const double norm = 1.0 / static_cast<double>(grid_.nb_cells());
  for (std::ptrdiff_t j = 0; j < sigma_.hy; ++j)
    for (std::ptrdiff_t i = 0; i < sigma_.hx; ++i)
      sigma_(i, j) = preconditioner_symbol(grid_, i, j, norm);
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
  const EvenMultiplier k_hat = filter_->even_spectrum(kernel.data(), 1.0);
  const double norm = 1.0 / static_cast<double>(grid_.nb_cells());
  // The factor sqrt(1 / (|k| K^)) of each mode, 1 for a half-space (up to a constant); the kernel
  // is even in both offsets: K^ is real and even, and so is the factor.
  EvenMultiplier factor(grid_.nx(), grid_.ny());
  const auto modes = static_cast<std::ptrdiff_t>(factor.values.size());
  if (grid_.nb_cells() == 1) return false;  // a single cell: only the mean, which |k|'s rule sets
  for (std::ptrdiff_t q = 1; q < modes; ++q) {
    const double k = k_hat.values[static_cast<std::size_t>(q)];
    if (!(k > 0) || !std::isfinite(k)) return false;
    factor.values[static_cast<std::size_t>(q)] =
        std::sqrt(1.0 / (preconditioner_symbol(grid_, q % factor.hx, q / factor.hx, 1.0) * k));
  }
  factor(0, 0) = grid_.ny() > 1 ? factor(0, 1) : factor(1, 0);  // mode (0, 1), else (1, 0)
  for (std::ptrdiff_t j = 0; j < sigma_.hy; ++j)
    for (std::ptrdiff_t i = 0; i < sigma_.hx; ++i)
      sigma_(i, j) = preconditioner_symbol(grid_, i, j, norm) * factor(i, j);
  return true;
}

void FourierPreconditioner::apply(double* z) {
  filter_->apply(z, z, sigma_);
}

}  // namespace coatfft::detail
