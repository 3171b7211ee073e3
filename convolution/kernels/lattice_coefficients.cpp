#include "convolution/kernels/lattice_coefficients.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

#include "convolution/fft/parity_transform.hpp"
#include "convolution/kernels/detail/ewald_window.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/sinc.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/threads.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

using detail::sinc;

// One lattice of the split: (mx, my) = alpha (nx, ny) points of spacing (dx, dy); the part of
// the spectrum it samples (weight w, 1 - w or 1), its alias orders and the quarter it fills.
struct SplitLattice {
  std::ptrdiff_t mx, my, hx, hy;
  double dkx, dky, k_cut, sigma;
  int px = 0, py = 0;
  bool long_range = false;
  bool band = false;  // the long-range part lies below Nyquist: no aliases, a band transform
};

SplitLattice make_lattice(const Grid& grid, double k_cut, int alpha, bool long_range, double sigma,
                          int max_order, LatticeReport& report) {
  SplitLattice l{};
  l.mx = alpha * grid.nx();
  l.my = alpha * grid.ny();
  l.dkx = 2.0 * pi / (static_cast<double>(l.mx) * grid.dx());
  l.dky = 2.0 * pi / (static_cast<double>(l.my) * grid.dy());
  l.sigma = sigma;
  l.long_range = long_range;
  // The window is below 1e-16 beyond sqrt(45)/sigma.
  l.k_cut = long_range ? std::min(k_cut, std::sqrt(45.0) / sigma) : k_cut;
  const auto order = [&](double h) {
    const double needed = std::ceil(l.k_cut * h / (2.0 * pi)) + 1.0;
    if (needed <= max_order) return static_cast<int>(needed);
    report.alias_capped = true;
    return max_order;
  };
  l.px = order(grid.dx());
  l.py = order(grid.dy());
  l.hx = l.mx / 2 + 1;
  l.hy = l.my / 2 + 1;
  if (long_range && l.k_cut * grid.dx() < pi && l.k_cut * grid.dy() < pi) {
    l.band = true;
    l.px = l.py = 0;
    l.hx = std::min(l.hx, static_cast<std::ptrdiff_t>(l.k_cut / l.dkx) + 1);
    l.hy = std::min(l.hy, static_cast<std::ptrdiff_t>(l.k_cut / l.dky) + 1);
  } else {
    report.alias_order = std::max({report.alias_order, l.px, l.py});
  }
  return l;
}

// The alias-folded quarters G_c(jx, jy) of one lattice.
std::vector<Field> sample_quarters(const Grid& grid, const LatticeSpectra& s, const SplitLattice& l,
                                   int threads, long long& evaluations) {
  const std::size_t nc = s.parity.size();
  std::vector<Field> g(nc, Field::Zero(l.hx, l.hy));
  std::atomic<long long> count{0};
  detail::parallel_for(0, l.hy, threads, [&](std::ptrdiff_t jy) {
    long long local = 0;
    std::vector<double> acc(nc), value(nc);
    for (std::ptrdiff_t jx = 0; jx < l.hx; ++jx) {
      // A row of a thin coating's lattice folds thousands of aliases per point: seconds.
      check_interrupt();
      std::fill(acc.begin(), acc.end(), 0.0);
      for (int p = -l.px; p <= l.px; ++p) {
        const double kx = static_cast<double>(jx) * l.dkx + 2.0 * pi * p / grid.dx();
        const double wx = sinc(0.5 * kx * grid.dx());
        for (int q = -l.py; q <= l.py; ++q) {
          const double ky = static_cast<double>(jy) * l.dky + 2.0 * pi * q / grid.dy();
          const double k = std::hypot(kx, ky);
          if (k == 0.0 || k > l.k_cut) continue;
          const double part = l.long_range ? detail::ewald_window(l.sigma, k)
                                           : detail::ewald_window_complement(l.sigma, k);
          s.sample(kx, ky, k, value);
          ++local;
          const double w = wx * sinc(0.5 * ky * grid.dy()) * part;
          for (std::size_t c = 0; c < nc; ++c) acc[c] += w * value[c];
        }
      }
      for (std::size_t c = 0; c < nc; ++c) g[c](jx, jy) = acc[c];
    }
    count += local;
  });
  evaluations += count.load();
  return g;
}

void add_lattice(const Grid& grid, const LatticeSpectra& s, const SplitLattice& l, int threads,
                 std::vector<Field>& out, long long& evaluations) {
  const std::vector<Field> g = sample_quarters(grid, s, l, threads, evaluations);
  const double scale = 1.0 / (static_cast<double>(l.mx) * static_cast<double>(l.my));
  for (std::size_t c = 0; c < g.size(); ++c) {
    const auto [odd_x, odd_y] = s.parity[c];
    if (l.band) {
      out[c] += scale * band_parity_transform(g[c], odd_x, odd_y, l.mx, l.my, grid.nx(), grid.ny());
    } else {
      out[c] += scale * parity_transform(g[c], odd_x, odd_y).topLeftCorner(grid.nx(), grid.ny());
    }
  }
}

}  // namespace

double exponential_cut_off(double z, double tolerance) {
  const double log_tol = std::log(1.0 / tolerance);
  return (log_tol + 2.0 * std::log1p(log_tol) + 3.0) / z;
}

double lattice_evaluations(const Grid& grid, double k_cut, int alpha) {
  const double cell = (pi / grid.lx()) * (pi / grid.ly());
  const double lattice = (grid.nx() + 1.0) * (grid.ny() + 1.0);
  return std::max(0.25 * pi * k_cut * k_cut / cell, lattice) +
         (alpha > 2 ? std::pow(34.0 * alpha, 2) : 0.0);
}

std::vector<Field> lattice_coefficients(const Grid& grid, const LatticeSpectra& spectra,
                                        const LatticeOptions& o, const char* what,
                                        LatticeReport* report) {
  COATFFT_REQUIRE(o.alpha >= 2, what, ": alpha must be an integer >= 2");
  COATFFT_REQUIRE(o.max_alias_order >= 0, what, ": max_alias_order must be >= 0");
  COATFFT_REQUIRE(o.threads >= 1 && o.threads <= max_threads, what, ": threads must be in [1, ",
                  max_threads, "]");
  COATFFT_REQUIRE(grid.nx() <= (1 << 20) / o.alpha && grid.ny() <= (1 << 20) / o.alpha, what,
                  ": alpha times the cell count exceeds 2^20 along an axis");
  COATFFT_REQUIRE(std::isfinite(spectra.k_cut) && spectra.k_cut > 0, what,
                  ": k_cut = ", spectra.k_cut, " rad/m must be finite and > 0");
  const double estimate = lattice_evaluations(grid, spectra.k_cut, o.alpha);
  COATFFT_REQUIRE(estimate <= o.max_evaluations, what,
                  ": the spectra reach k = ", detail::brief(spectra.k_cut),
                  " rad/m, so far against the domain (", detail::brief(grid.lx()), " x ",
                  detail::brief(grid.ly()), " m) that about ", detail::brief(estimate),
                  " FRF evaluations are needed (limit ", detail::brief(o.max_evaluations), ")");
  LatticeReport r;
  std::vector<Field> out(spectra.parity.size(), Field::Zero(grid.nx(), grid.ny()));
  const int threads = o.threads;
  if (o.alpha == 2) {
    SplitLattice whole = make_lattice(grid, spectra.k_cut, 2, false, 0.0, o.max_alias_order, r);
    add_lattice(grid, spectra, whole, threads, out, r.evaluations);
  } else {
    // The short-range part on DC-FFT's own lattice (its images, >= L = 32 sigma away, are
    // negligible), the band-limited long-range part on the alpha-extended one.
    const double sigma = std::min(grid.lx(), grid.ly()) / 32.0;
    add_lattice(grid, spectra,
                make_lattice(grid, spectra.k_cut, 2, false, sigma, o.max_alias_order, r), threads,
                out, r.evaluations);
    add_lattice(grid, spectra,
                make_lattice(grid, spectra.k_cut, o.alpha, true, sigma, o.max_alias_order, r),
                threads, out, r.evaluations);
  }
  if (report) *report = r;
  return out;
}

}  // namespace coatfft
