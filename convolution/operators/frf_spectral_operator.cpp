#include "convolution/operators/detail/frf_spectral_operator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

namespace coatfft {

FrfSpectralOperator::FrfSpectralOperator(const Grid& grid, const Frf& frf, double alpha,
                                         G0Method g0_method, double g0_tolerance, Planning planning,
                                         int threads)
    : FrfSpectralOperator(
          grid, frf, alpha,
          lattice_g0(grid, frf, alpha, 1.0, g0_method, g0_tolerance, "FrfSpectralOperator"),
          planning, threads) {
  // The delegated constructor timed only itself; add the g(0) computation done before it.
  setup_seconds_ += g0_.seconds;
}

FrfSpectralOperator::FrfSpectralOperator(const Grid& grid, const Frf& frf, double alpha,
                                         const G0Result& g0, Planning planning, int threads)
    : grid_(grid),
      alpha_(alpha),
      mx_(extended_size(grid.nx(), alpha, 1.0, "FrfSpectralOperator")),
      my_(extended_size(grid.ny(), alpha, 1.0, "FrfSpectralOperator")),
      hx_(mx_ / 2 + 1),
      g0_(g0) {
  const auto start = std::chrono::steady_clock::now();
  COATFFT_REQUIRE(std::isfinite(g0.value), "FrfSpectralOperator: g(0) = ", g0.value,
                  " m/Pa, but it must be finite");
  COATFFT_REQUIRE(threads >= 1, "FrfSpectralOperator: threads = ", threads, ", but must be >= 1");
  const auto nreal = static_cast<std::size_t>(mx_ * my_);
  const auto nhalf = static_cast<std::size_t>(hx_ * my_);
  real_ = FftwRealBuffer(nreal);
  spectrum_ = FftwComplexBuffer(nhalf);
  // FFTW is row-major: the Field layout (x fastest) is a C array {my, mx}.
  const unsigned flags = fftw_flags(planning);
  const int m0 = static_cast<int>(my_), m1 = static_cast<int>(mx_);
  forward_ = FftwPlan::create(
      threads, [&] { return fftw_plan_dft_r2c_2d(m0, m1, real_.data(), spectrum_.data(), flags); });
  backward_ = FftwPlan::create(
      threads, [&] { return fftw_plan_dft_c2r_2d(m0, m1, spectrum_.data(), real_.data(), flags); });
  // H is real and even, so the product with the half spectrum of p needs only real factors;
  // FFTW's unnormalised inverse is compensated here, once (docs/conventions.md). With the
  // numpy-style 1/(mx my) no further factor is needed because the period is exactly mx dx
  // (docs/theory.md 4.3).
  // Only the quarter |jy| <= my/2 is sampled and kept (no (my, hx) array: at alpha = 4 and
  // 1024^2 that is 67 MB less to fill and fault in, and half the kernel memory).
  using std::numbers::pi;
  kernel_quarter_ = detail::sample_frf_quarter(
      frf, hx_, my_ / 2 + 1, 2.0 * pi / (static_cast<double>(mx_) * grid.dx()),
      2.0 * pi / (static_cast<double>(my_) * grid.dy()), threads);
  kernel_quarter_(0, 0) = g0.value;
  kernel_quarter_ *= 1.0 / (static_cast<double>(mx_) * static_cast<double>(my_));
  setup_seconds_ = detail::seconds_since(start);
}

void FrfSpectralOperator::apply(const Field& pressure, Field& displacement) {
  const std::ptrdiff_t nx = grid_.nx(), ny = grid_.ny();
  COATFFT_REQUIRE(pressure.rows() == nx && pressure.cols() == ny,
                  "FrfSpectralOperator::apply: pressure has shape (", pressure.rows(), ", ",
                  pressure.cols(), "), but the grid needs (", nx, ", ", ny, ")");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "FrfSpectralOperator::apply: displacement must not alias pressure");
  // Pressure in the block [0, nx) x [0, ny) of the extended lattice, zeros elsewhere (Spinu
  // 2021, section 4, step 5). The product is a circular convolution
  // u_i = sum_k G_{(i-k) mod M} p_k, so the displacement of target cell i lies in slot i: the
  // block kept is [0, nx) x [0, ny), as in docs/theory.md 4.3. Spinu's "retain the middle N
  // terms" (step 9) describes a layout with the pressure placed in the middle of the extended
  // window; both give the same values.
  double* r = real_.data();
  std::fill_n(r, mx_ * my_, 0.0);
  for (std::ptrdiff_t j = 0; j < ny; ++j) std::copy_n(&pressure(0, j), nx, r + j * mx_);
  forward_.execute();
  std::complex<double>* s = as_complex(spectrum_.data());
  for (std::ptrdiff_t jy = 0; jy < my_; ++jy) {
    const double* k = &kernel_quarter_(0, detail::folded_index(jy, my_));
    std::complex<double>* row = s + jy * hx_;
    for (std::ptrdiff_t jx = 0; jx < hx_; ++jx) row[jx] *= k[jx];
  }
  backward_.execute();
  displacement.resize(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j) std::copy_n(r + j * mx_, nx, &displacement(0, j));
}

}  // namespace coatfft
