#include "convolution/frf_influence_kernel.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <utility>

#include "convolution/fftw_plan.hpp"
#include "convolution/frf_spectral_operator.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

constexpr const char* who = "frf_influence_kernel";

double sinc(double x) {
  return x == 0.0 ? 1.0 : std::sin(x) / x;
}

}  // namespace

InfluenceKernel frf_influence_kernel(const Grid& grid, const Frf& frf, double alpha,
                                     G0Method g0_method, double g0_tolerance, G0Result* g0_used) {
  using std::numbers::pi;
  const std::ptrdiff_t mx = extended_size(grid.nx(), alpha, 2.0, who);
  const std::ptrdiff_t my = extended_size(grid.ny(), alpha, 2.0, who);
  const G0Result g0 =
      compute_g0(frf, 2.0 * pi / (static_cast<double>(mx) * grid.dx()),
                 2.0 * pi / (static_cast<double>(my) * grid.dy()), g0_method, g0_tolerance);
  if (g0_used != nullptr) *g0_used = g0;
  return frf_influence_kernel(grid, frf, alpha, g0);
}

InfluenceKernel frf_influence_kernel(const Grid& grid, const Frf& frf, double alpha,
                                     const G0Result& g0, int threads) {
  (void)threads;
  using std::numbers::pi;
  const std::ptrdiff_t nx = grid.nx(), ny = grid.ny();
  const std::ptrdiff_t mx = extended_size(nx, alpha, 2.0, who);
  const std::ptrdiff_t my = extended_size(ny, alpha, 2.0, who);
  const std::ptrdiff_t hx = mx / 2 + 1;
  COATFFT_REQUIRE(std::isfinite(g0.value), who, ": g(0) = ", g0.value,
                  " m/Pa, but it must be finite");
  const double dx = grid.dx(), dy = grid.dy();
  const double dkx = 2.0 * pi / (static_cast<double>(mx) * dx);
  const double dky = 2.0 * pi / (static_cast<double>(my) * dy);

  // theory.md (4.1): the coefficient of a uniformly loaded dx x dy cell is the Fourier series of
  // the periodised G convolved with the cell's indicator, whose transform is
  // dx dy sinc(kx dx/2) sinc(ky dy/2); the dx dy cancels the 1/(mx dx my dy) of the series, which
  // leaves FFTW's 1/(mx my). The seed paper's step list does not mention the cell factor (it
  // inverts the bare FRF samples, i.e. point-sampled coefficients); we implement (4.1), which is
  // the consistent cell average and differs from the bare samples mostly near the self term.
  Field h = sample_frf_half_spectrum(frf, mx, my, dx, dy, g0.value);
  FftwComplexBuffer spectrum(static_cast<std::size_t>(hx * my));
  FftwRealBuffer space(static_cast<std::size_t>(mx * my));
  const FftwPlan c2r = FftwPlan::create(1, [&] {
    return fftw_plan_dft_c2r_2d(static_cast<int>(my), static_cast<int>(mx), spectrum.data(),
                                space.data(), FFTW_ESTIMATE);
  });
  std::complex<double>* s = as_complex(spectrum.data());
  const double scale = 1.0 / (static_cast<double>(mx) * static_cast<double>(my));
  for (std::ptrdiff_t jy = 0; jy < my; ++jy) {
    const std::ptrdiff_t sy = jy < (my + 1) / 2 ? jy : jy - my;
    const double sy_factor = sinc(0.5 * dky * static_cast<double>(sy) * dy);
    for (std::ptrdiff_t jx = 0; jx < hx; ++jx) {
      const double sx_factor = sinc(0.5 * dkx * static_cast<double>(jx) * dx);
      s[jy * hx + jx] = scale * h(jx, jy) * sx_factor * sy_factor;
    }
  }
  c2r.execute();

  // Offsets d with |d| <= n - 1 sit at (d mod m) on the M lattice; alpha >= 2 keeps the images
  // of +d and -d apart. Copy them into DC-FFT's (2nx, 2ny) wrap-around layout.
  Field wrapped = Field::Zero(2 * nx, 2 * ny);
  const double* k = space.data();
  for (std::ptrdiff_t dj = -(ny - 1); dj <= ny - 1; ++dj) {
    const std::ptrdiff_t mj = dj >= 0 ? dj : my + dj;
    const std::ptrdiff_t wj = dj >= 0 ? dj : 2 * ny + dj;
    for (std::ptrdiff_t di = -(nx - 1); di <= nx - 1; ++di) {
      const std::ptrdiff_t mi = di >= 0 ? di : mx + di;
      const std::ptrdiff_t wi = di >= 0 ? di : 2 * nx + di;
      wrapped(wi, wj) = k[mj * mx + mi];
    }
  }
  return InfluenceKernel(grid, std::move(wrapped));
}

}  // namespace coatfft
