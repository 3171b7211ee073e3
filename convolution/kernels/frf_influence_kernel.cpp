#include "convolution/kernels/frf_influence_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <utility>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/detail/frf_lattice.hpp"
#include "core/detail/sinc.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

constexpr const char* kernel_name = "frf_influence_kernel";

using detail::sinc;

}  // namespace

InfluenceKernel frf_influence_kernel(const Grid& grid, const Frf& frf, double alpha,
                                     G0Method g0_method, double g0_tolerance, G0Result* g0_used,
                                     int threads) {
  const G0Result g0 = lattice_g0(grid, frf, alpha, 2.0, g0_method, g0_tolerance, kernel_name);
  if (g0_used != nullptr) *g0_used = g0;
  return frf_influence_kernel(grid, frf, alpha, g0, threads);
}

namespace detail {

Field frf_cell_spectrum_quarter(const Grid& grid, const Frf& frf, std::ptrdiff_t mx,
                                std::ptrdiff_t my, const G0Result& g0, int threads) {
  using std::numbers::pi;
  const double dx = grid.dx(), dy = grid.dy();
  const double dkx = 2.0 * pi / (static_cast<double>(mx) * dx);
  const double dky = 2.0 * pi / (static_cast<double>(my) * dy);
  const std::ptrdiff_t qx = mx / 2 + 1, qy = my / 2 + 1;
  Field q = sample_frf_quarter(frf, qx, qy, dkx, dky, threads);
  q(0, 0) = g0.value;
  // The cell factors sinc(kx dx/2) sinc(ky dy/2), tabulated per axis (2 sin per point otherwise).
  std::vector<double> sinc_x(static_cast<std::size_t>(qx));
  for (std::ptrdiff_t j = 0; j < qx; ++j)
    sinc_x[static_cast<std::size_t>(j)] = sinc(0.5 * dkx * static_cast<double>(j) * dx);
  for (std::ptrdiff_t jy = 0; jy < qy; ++jy) {
    const double sy = sinc(0.5 * dky * static_cast<double>(jy) * dy);
    for (std::ptrdiff_t jx = 0; jx < qx; ++jx)
      q(jx, jy) *= sinc_x[static_cast<std::size_t>(jx)] * sy;
  }
  return q;
}

}  // namespace detail

InfluenceKernel frf_influence_kernel(const Grid& grid, const Frf& frf, double alpha,
                                     const G0Result& g0, int threads) {
  using std::numbers::pi;
  const std::ptrdiff_t nx = grid.nx(), ny = grid.ny();
  const std::ptrdiff_t mx = extended_size(nx, alpha, 2.0, kernel_name);
  const std::ptrdiff_t my = extended_size(ny, alpha, 2.0, kernel_name);
  COATFFT_REQUIRE(std::isfinite(g0.value), kernel_name, ": g(0) = ", g0.value,
                  " m/Pa, but it must be finite");
  COATFFT_REQUIRE(threads >= 1, kernel_name, ": threads = ", threads, ", but must be >= 1");
  const double dx = grid.dx(), dy = grid.dy();
  const double dkx = 2.0 * pi / (static_cast<double>(mx) * dx);
  const double dky = 2.0 * pi / (static_cast<double>(my) * dy);
  const double scale = 1.0 / (static_cast<double>(mx) * static_cast<double>(my));

  // docs/theory.md (4.1): the coefficient of a uniformly loaded dx x dy cell is the Fourier series
  // of the periodised G convolved with the cell's indicator, whose transform is
  // dx dy sinc(kx dx/2) sinc(ky dy/2); the dx dy cancels the 1/(mx dx my dy) of the series, which
  // leaves FFTW's 1/(mx my). The step list of Spinu (2021) does not mention the cell factor (it
  // inverts the bare FRF samples, i.e. point-sampled coefficients); we implement (4.1), which is
  // the consistent cell average and differs from the bare samples mostly near the self term.
  //
  // The spectrum H sinc sinc is real and even in kx and in ky, so its inverse DFT on the
  // (mx, my) lattice is a 2-D DCT-I of the quarter 0 <= jx <= mx/2, 0 <= jy <= my/2 when both
  // sizes are even (FFTW REDFT00; the same identity DcfftOperator uses): a quarter of the FRF
  // samples and a transform of (mx/2 + 1) x (my/2 + 1) instead of a c2r of mx x my. The result
  // is then exactly even, so the offsets -d are copies of +d (alpha >= 2 keeps the images of +d
  // and -d apart) and DcfftOperator stores a real spectrum. Odd sizes take the c2r route.
  const std::ptrdiff_t qx = mx / 2 + 1;
  std::vector<double> sinc_x(static_cast<std::size_t>(qx));
  for (std::ptrdiff_t j = 0; j < qx; ++j)
    sinc_x[static_cast<std::size_t>(j)] = sinc(0.5 * dkx * static_cast<double>(j) * dx);
  const auto sinc_y = [&](std::ptrdiff_t sy) {
    return sinc(0.5 * dky * static_cast<double>(sy) * dy);
  };

  // The quarter of the coefficients: column dj holds K(di, dj) for di = 0..nx-1 (k_column).
  Field quarter = Field::Zero(nx + 1, ny + 1);
  const auto fill_column = [&](std::ptrdiff_t dj, const double* k_column) {
    std::copy_n(k_column, nx, &quarter(0, dj));
  };

  if (mx % 2 == 0 && my % 2 == 0) {
    const std::ptrdiff_t qy = my / 2 + 1;
    Field q = detail::frf_cell_spectrum_quarter(grid, frf, mx, my, g0, threads);
    q *= scale;
    // In place on the Field (FFTW_ESTIMATE plans without touching it; Eigen's alignment is
    // checked by FFTW at planning and the plan runs on this same array): no second 8 MiB buffer
    // to zero, copy and page in at 1024^2. FFTW is row-major: the Field (x fastest) is {qy, qx}.
    double* dct = q.data();
    const FftwPlan plan = FftwPlan::create(threads, [&] {
      return fftw_plan_r2r_2d(static_cast<int>(qy), static_cast<int>(qx), dct, dct, FFTW_REDFT00,
                              FFTW_REDFT00, FFTW_ESTIMATE);
    });
    plan.execute();
    for (std::ptrdiff_t dj = 0; dj < ny; ++dj) fill_column(dj, dct + dj * qx);
  } else {
    const Field h = sample_frf_half_spectrum(frf, mx, my, dx, dy, g0.value, threads);
    FftwComplexBuffer spectrum(static_cast<std::size_t>(qx * my));
    FftwRealBuffer space(static_cast<std::size_t>(mx * my));
    const FftwPlan c2r = FftwPlan::create(threads, [&] {
      return fftw_plan_dft_c2r_2d(static_cast<int>(my), static_cast<int>(mx), spectrum.data(),
                                  space.data(), FFTW_ESTIMATE);
    });
    std::complex<double>* s = as_complex(spectrum.data());
    for (std::ptrdiff_t jy = 0; jy < my; ++jy) {
      const double fy = scale * sinc_y(detail::folded_index(jy, my));
      for (std::ptrdiff_t jx = 0; jx < qx; ++jx)
        s[jy * qx + jx] = h(jx, jy) * sinc_x[static_cast<std::size_t>(jx)] * fy;
    }
    c2r.execute();
    // The inverse of a real even spectrum is even up to rounding: the offsets +d (slots d on the
    // M lattice) are kept, as on the DCT route, and stand for -d too.
    for (std::ptrdiff_t dj = 0; dj < ny; ++dj) fill_column(dj, space.data() + dj * mx);
  }
  return InfluenceKernel(grid, InfluenceKernel::Form::coefficients, std::move(quarter),
                         Method::frf_dcfft);
}

InfluenceKernel frf_dcfft_kernel(const Grid& grid, const Frf& frf, double alpha, const G0Result& g0,
                                 int threads) {
  const std::ptrdiff_t mx = extended_size(grid.nx(), alpha, 2.0, kernel_name);
  const std::ptrdiff_t my = extended_size(grid.ny(), alpha, 2.0, kernel_name);
  if (mx != 2 * grid.nx() || my != 2 * grid.ny())
    return frf_influence_kernel(grid, frf, alpha, g0, threads);
  // At alpha = 2 the extended lattice is DC-FFT's own padded (2nx, 2ny) lattice, so the sampled
  // spectrum H sinc sinc *is* the spectrum DC-FFT would get back from the coefficients: the
  // inverse transform and the forward transform are skipped (the round trip only drops the
  // offsets +-nx, +-ny, which never reach the cropped output).
  COATFFT_REQUIRE(std::isfinite(g0.value), kernel_name, ": g(0) = ", g0.value,
                  " m/Pa, but it must be finite");
  COATFFT_REQUIRE(threads >= 1, kernel_name, ": threads = ", threads, ", but must be >= 1");
  return InfluenceKernel(grid, InfluenceKernel::Form::spectrum,
                         detail::frf_cell_spectrum_quarter(grid, frf, mx, my, g0, threads),
                         Method::frf_dcfft);
}

}  // namespace coatfft
