#include "surfaces/self_affine_surface.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <span>
#include <string_view>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "surfaces/detail/self_affine_spectrum.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

// The half spectrum of FFTW's r2c layout for a (nx, ny) Field (x fastest): (nx/2 + 1) x ny
// complex entries, entry (i, j) at j (nx/2 + 1) + i, wavevector 2 pi (i/lx, s(j)/ly) with s(j)
// the signed frequency of j.
struct HalfSpectrum {
  std::ptrdiff_t hx, ny;
  FftwComplexBuffer data;
  HalfSpectrum(std::ptrdiff_t nx, std::ptrdiff_t ny_)
      : hx(nx / 2 + 1), ny(ny_), data(static_cast<std::size_t>(hx * ny_)) {}
  std::complex<double>& at(std::ptrdiff_t i, std::ptrdiff_t j) {
    return as_complex(data.data())[j * hx + i];
  }
};

std::ptrdiff_t signed_frequency(std::ptrdiff_t j, std::ptrdiff_t n) {
  return j <= n / 2 ? j : j - n;
}

double wavenumber(const Grid& g, std::ptrdiff_t i, std::ptrdiff_t j) {
  return std::hypot(2.0 * pi * static_cast<double>(i) / g.lx(),
                    2.0 * pi * static_cast<double>(signed_frequency(j, g.ny())) / g.ly());
}

// A uniform number in [0, 1) from the top 53 bits: the same sequence with every standard
// library (std::uniform_real_distribution is implementation-defined).
double uniform(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

struct Cutoffs {
  double q_r, q_s;
};

Cutoffs validate_spectrum(const Grid& g, const SelfAffineSpec& s) {
  COATFFT_REQUIRE(g.nx() >= 2 && g.ny() >= 2 && g.nx() % 2 == 0 && g.ny() % 2 == 0,
                  "self-affine surface: nx = ", g.nx(), " and ny = ", g.ny(),
                  " must be even and >= 2");
  COATFFT_REQUIRE(std::isfinite(s.hurst) && s.hurst > 0 && s.hurst <= 1,
                  "self-affine surface: the Hurst exponent ", s.hurst, " must be in (0, 1]");
  COATFFT_REQUIRE(s.rms_height.has_value() != s.rms_slope.has_value(),
                  "self-affine surface: give exactly one of the rms height and the rms slope");
  const double nyquist_wavelength = 2.0 * std::max(g.dx(), g.dy());
  const double lambda_s = s.short_cutoff.value_or(nyquist_wavelength);
  const double lambda_r = s.long_cutoff.value_or(std::max(g.lx(), g.ly()));
  COATFFT_REQUIRE(std::isfinite(lambda_s) && lambda_s >= nyquist_wavelength * (1 - 1e-12),
                  "self-affine surface: the short cut-off ", lambda_s,
                  " m is below the grid's shortest wavelength 2 max(dx, dy) = ", nyquist_wavelength,
                  " m");
  COATFFT_REQUIRE(std::isfinite(lambda_r) && lambda_r > lambda_s,
                  "self-affine surface: the long cut-off ", lambda_r,
                  " m must be finite and above the short cut-off ", lambda_s, " m");
  return {2.0 * pi / lambda_r, 2.0 * pi / lambda_s};
}

// C(q)^(1/2) for C0 = 1.
double amplitude(double q, double hurst, const Cutoffs& c) {
  if (q == 0.0 || q > c.q_s * (1 + 1e-12)) return 0.0;
  return std::pow(std::max(q, c.q_r) / c.q_r, -(1.0 + hurst));
}

using detail::SpectrumMoments;

// The requested rms within the limits of the header, and for an rms slope the rms height it gives.
void check_rms(const SelfAffineSpec& s, const SpectrumMoments& m, std::string_view height_name,
               std::string_view slope_name) {
  COATFFT_REQUIRE(m.height2 > 0, "self-affine surface: no Fourier mode lies between the cut-offs");
  if (s.rms_height) {
    const double h = *s.rms_height;
    COATFFT_REQUIRE(std::isfinite(h) && h >= min_rms_height && h <= max_rms_height,
                    "self-affine surface: ", height_name, " = ", h, " m must be in [",
                    min_rms_height, ", ", max_rms_height, "] m (docs/surfaces.md, \"Limits\")");
    return;
  }
  const double slope = *s.rms_slope;
  COATFFT_REQUIRE(std::isfinite(slope) && slope > 0 && slope <= max_rms_slope,
                  "self-affine surface: ", slope_name, " = ", slope, " must be in (0, ",
                  max_rms_slope, "] (docs/surfaces.md, \"Limits\")");
  const double height = slope * std::sqrt(m.height2 / m.slope2);
  COATFFT_REQUIRE(height >= min_rms_height && height <= max_rms_height,
                  "self-affine surface: ", slope_name, " = ", slope, " gives an rms height of ",
                  height, " m on this grid and spectrum, outside [", min_rms_height, ", ",
                  max_rms_height, "] m (docs/surfaces.md, \"Limits\")");
}

// The inverse DFT in the steps of the distributed surface's slab transform (distributed/
// slab_fft.hpp) on one rank: the half spectrum transposed into contiguous columns, FFTW's c2c of
// each column (along y), transposed back, FFTW's c2r of each row (along x). The same 1-D plans
// give the same numbers at any rank count; a 2-D plan differs from them by rounding (3e-16).
Field inverse(const Grid& g, HalfSpectrum& spec) {
  const int nx = static_cast<int>(g.nx()), ny = static_cast<int>(g.ny());
  const int hx = static_cast<int>(spec.hx);
  FftwComplexBuffer columns(spec.data.size());
  std::complex<double>* c = as_complex(columns.data());
  const FftwPlan along_y = FftwPlan::create(1, [&] {
    return fftw_plan_many_dft(1, &ny, hx, columns.data(), nullptr, 1, ny, columns.data(), nullptr,
                              1, ny, FFTW_BACKWARD, FFTW_ESTIMATE);
  });
  FftwRealBuffer out(static_cast<std::size_t>(g.nx() * g.ny()));
  const FftwPlan along_x = FftwPlan::create(1, [&] {
    return fftw_plan_many_dft_c2r(1, &nx, ny, spec.data.data(), nullptr, 1, hx, out.data(), nullptr,
                                  1, nx, FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
  for (std::ptrdiff_t j = 0; j < spec.ny; ++j)
    for (std::ptrdiff_t i = 0; i < spec.hx; ++i) c[i * spec.ny + j] = spec.at(i, j);
  along_y.execute();
  for (std::ptrdiff_t j = 0; j < spec.ny; ++j)
    for (std::ptrdiff_t i = 0; i < spec.hx; ++i) spec.at(i, j) = c[i * spec.ny + j];
  along_x.execute();
  return Eigen::Map<const Field>(out.data(), g.nx(), g.ny());
}

}  // namespace

namespace detail {

// By Parseval on the grid, the unscaled field's mean squares of height and slope are the sums of
// a^2 and |k|^2 a^2 over the modes: every mode has its amplitude a exactly, whatever its phase,
// so they fix the rms before any surface is made, and the same for any share of the rows.
std::vector<SpectrumMoments> self_affine_row_moments(const Grid& g, const SelfAffineSpec& s,
                                                     std::ptrdiff_t j0, std::ptrdiff_t j1) {
  const Cutoffs c = validate_spectrum(g, s);
  std::vector<SpectrumMoments> rows(static_cast<std::size_t>(j1 - j0));
  for (std::ptrdiff_t j = j0; j < j1; ++j) {
    SpectrumMoments& m = rows[static_cast<std::size_t>(j - j0)];
    for (std::ptrdiff_t i = 0; i <= g.nx() / 2; ++i) {
      const double weight = (i == 0 || i == g.nx() / 2) ? 1.0 : 2.0;
      const double q = wavenumber(g, i, j);
      const double a = amplitude(q, s.hurst, c);
      m.height2 += weight * a * a;
      m.slope2 += weight * q * q * a * a;
    }
  }
  return rows;
}

double mode_slope2(const Grid& g, std::ptrdiff_t i, std::ptrdiff_t j, std::complex<double> h_k) {
  const double weight = (i == 0 || i == g.nx() / 2) ? 1.0 : 2.0;
  const double k = wavenumber(g, i, j);
  return weight * k * k * std::norm(h_k);
}

double self_affine_scale(const SelfAffineSpec& s, std::span<const SpectrumMoments> rows,
                         std::string_view height_name, std::string_view slope_name) {
  SpectrumMoments m;
  for (const SpectrumMoments& row : rows) {
    m.height2 += row.height2;
    m.slope2 += row.slope2;
  }
  check_rms(s, m, height_name, slope_name);
  return s.rms_height ? *s.rms_height / std::sqrt(m.height2) : *s.rms_slope / std::sqrt(m.slope2);
}

// Random phases drawn in a fixed order, entry (i, j) the (j (nx/2 + 1) + i)-th number, with the
// symmetry that makes the field real: on the columns i = 0 and i = nx/2 (their own conjugates'
// column) the entry of -j is the conjugate of that of j, and the four self-conjugate entries are
// real (a random sign). Rows from j0 on: the generator skips the numbers of the rows before; the
// conjugates of rows before j0 come from a second generator that walks those rows.
void self_affine_rows(const Grid& g, const SelfAffineSpec& s, std::ptrdiff_t j0, std::ptrdiff_t j1,
                      std::complex<double>* rows) {
  const Cutoffs c = validate_spectrum(g, s);
  if (j1 <= j0) return;
  const std::ptrdiff_t nx = g.nx(), ny = g.ny(), hx = nx / 2 + 1;
  const auto a = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    return amplitude(wavenumber(g, i, j), s.hurst, c);
  };
  // The own columns' entries of rows m0 <= m < j0 whose conjugates lie in j0 <= j < j1.
  const std::ptrdiff_t m0 = std::max<std::ptrdiff_t>(ny - j1 + 1, 1);
  std::vector<std::complex<double>> before(
      static_cast<std::size_t>(2 * std::max<std::ptrdiff_t>(j0 - m0, 0)));
  const auto own = [&](std::ptrdiff_t m, std::ptrdiff_t i) {
    return static_cast<std::size_t>(2 * (m - m0) + (i == 0 ? 0 : 1));
  };
  std::mt19937_64 rng(s.seed);
  if (j0 > m0) {
    rng.discard(static_cast<unsigned long long>(m0 * hx));
    for (std::ptrdiff_t m = m0; m < j0; ++m)
      for (std::ptrdiff_t i = 0; i < hx; ++i) {
        const double phase = 2.0 * pi * uniform(rng);
        if (i == 0 || i == nx / 2) before[own(m, i)] = std::polar(a(i, m), phase);
      }
  } else {
    rng.discard(static_cast<unsigned long long>(j0 * hx));
  }
  const auto at = [&](std::ptrdiff_t i, std::ptrdiff_t j) -> std::complex<double>& {
    return rows[(j - j0) * hx + i];
  };
  for (std::ptrdiff_t j = j0; j < j1; ++j)
    for (std::ptrdiff_t i = 0; i < hx; ++i) {
      const double phase = 2.0 * pi * uniform(rng);
      const bool own_column = i == 0 || i == nx / 2;
      if (own_column && (j == 0 || j == ny / 2)) {
        at(i, j) = phase < pi ? a(i, j) : -a(i, j);
      } else if (own_column && j > ny / 2) {
        const std::ptrdiff_t m = ny - j;
        at(i, j) = std::conj(m >= j0 ? at(i, m) : before[own(m, i)]);
      } else {
        at(i, j) = std::polar(a(i, j), phase);
      }
    }
}

}  // namespace detail

double spectral_rms_slope(const Grid& g, const Field& h) {
  COATFFT_REQUIRE(h.rows() == g.nx() && h.cols() == g.ny(),
                  "spectral_rms_slope: the field is not of the grid's shape");
  FftwRealBuffer in(static_cast<std::size_t>(h.size()));
  std::copy(h.data(), h.data() + h.size(), in.data());
  HalfSpectrum spec(g.nx(), g.ny());
  const FftwPlan plan = FftwPlan::create(1, [&] {
    return fftw_plan_dft_r2c_2d(static_cast<int>(g.ny()), static_cast<int>(g.nx()), in.data(),
                                spec.data.data(), FFTW_ESTIMATE);
  });
  plan.execute();
  // Parseval on the grid: mean |grad h|^2 = sum over every mode of |k|^2 |h_k|^2, h_k the FFT over
  // the cell count; the half spectrum holds the modes i and -i once for 0 < i < nx/2.
  const double cells = static_cast<double>(h.size());
  double sum = 0.0;
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < spec.hx; ++i)
      sum += detail::mode_slope2(g, i, j, spec.at(i, j)) / (cells * cells);
  return std::sqrt(sum);
}

void require_self_affine_memory(const Grid& grid, std::string_view who) {
  // The half spectrum (about a field of doubles), its column-transformed copy, the real output
  // and the scaled field returned: four fields at the peak.
  require_grid_memory(grid.nx(), grid.ny(), 4.0, who);
}

void check_self_affine_spec(const Grid& grid, const SelfAffineSpec& spec,
                            std::string_view height_name, std::string_view slope_name) {
  COATFFT_REQUIRE(grid.nx() <= max_surface_cells && grid.ny() <= max_surface_cells, "grid ",
                  grid.nx(), " x ", grid.ny(), ": a surface has at most ", max_surface_cells,
                  " cells a side");
  detail::self_affine_scale(spec, detail::self_affine_row_moments(grid, spec, 0, grid.ny()),
                            height_name, slope_name);
}

Field self_affine_surface(const Grid& grid, const SelfAffineSpec& spec) {
  require_self_affine_memory(grid, "self_affine_surface");
  const double scale =
      detail::self_affine_scale(spec, detail::self_affine_row_moments(grid, spec, 0, grid.ny()));
  HalfSpectrum half(grid.nx(), grid.ny());
  detail::self_affine_rows(grid, spec, 0, grid.ny(), as_complex(half.data.data()));
  return inverse(grid, half) * scale;
}

}  // namespace coatfft
