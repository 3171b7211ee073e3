#include "stress/stress_kernel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "convolution/fft/parity_transform.hpp"
#include "convolution/kernels/detail/ewald_window.hpp"
#include "convolution/kernels/lattice_coefficients.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/sinc.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/threads.hpp"
#include "frf/stress_frf.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

using detail::sinc;

// The sampling lattice: (mx, my) = alpha (nx, ny) points of spacing (dx, dy), wavenumber steps
// 2 pi / (mx dx); aliases p 2 pi / dx up to order (px, py), those of the shallowest plane; the
// FRF terms of plane d beyond |k| > k_cut[d] dropped.
// Which part of the Ewald-type split a lattice samples (docs/stress.md): the whole spectrum, its
// long-range part S w (band-limited: |k| < sqrt(45)/sigma, where w < 1e-16) or its short-range
// part S (1 - w).
enum class Part { whole, long_range, short_range };

struct StressLattice {
  std::ptrdiff_t mx, my;
  double dx, dy, dkx, dky;
  std::vector<double> k_cut;
  int px, py;
  Part part;
  double sigma;           // window length [m]
  std::ptrdiff_t hx, hy;  // extent of the quarter sampled: (mx/2 + 1, my/2 + 1), or the band
  bool band = false;      // the long-range part lies below Nyquist: no aliases, a band transform
};

double part_weight(const StressLattice& l, double k) {
  switch (l.part) {
    case Part::long_range:
      return detail::ewald_window(l.sigma, k);
    case Part::short_range:
      return detail::ewald_window_complement(l.sigma, k);
    default:
      return 1.0;
  }
}

void validate(const Grid& grid, std::span<const double> depths, const StressKernelOptions& o) {
  if (depths.empty()) throw InvalidArgument("stress kernel: no depth given");
  for (double depth : depths)
    if (!std::isfinite(depth) || depth < 0.0)
      throw InvalidArgument("stress kernel: depth must be finite and >= 0 [m]");
  if (o.alpha < 2) throw InvalidArgument("stress kernel: alpha must be an integer >= 2");
  if (!(o.tolerance > 0.0 && o.tolerance <= 1e-3))
    throw InvalidArgument("stress kernel: tolerance must be in (0, 1e-3]");
  if (o.max_alias_order < 0) throw InvalidArgument("stress kernel: max_alias_order must be >= 0");
  if (o.threads < 1 || o.threads > max_threads)
    throw InvalidArgument("stress kernel: threads must be in [1, " + std::to_string(max_threads) +
                          "]");
  if (grid.nx() > (1 << 20) / o.alpha || grid.ny() > (1 << 20) / o.alpha)
    throw InvalidArgument("stress kernel: alpha times the cell count exceeds 2^20 along an axis");
}

// Every stress FRF at depth z is bounded by a polynomial of degree <= 2 in k z times exp(-k z)
// (docs/theory.md 2.7: the fields of the top pair; reflected waves decay faster), so the terms
// with k z > ln(1/tol) + 2 ln(1 + ln(1/tol)) + 3 are below tol.
StressLattice make_lattice(const Grid& grid, std::span<const double> depths,
                           const StressKernelOptions& o, int alpha, Part part, double sigma,
                           std::vector<StressKernelReport>* reports) {
  StressLattice l{};
  l.mx = alpha * grid.nx();
  l.my = alpha * grid.ny();
  l.dx = grid.dx();
  l.dy = grid.dy();
  l.dkx = 2.0 * pi / (static_cast<double>(l.mx) * l.dx);
  l.dky = 2.0 * pi / (static_cast<double>(l.my) * l.dy);
  l.part = part;
  l.sigma = sigma;
  const double band =
      part == Part::long_range ? std::sqrt(45.0) / sigma : std::numeric_limits<double>::infinity();
  for (std::size_t d = 0; d < depths.size(); ++d) {
    const double k_cut =
        std::min(band, depths[d] > 0.0 ? exponential_cut_off(depths[d], o.tolerance)
                                       : std::numeric_limits<double>::infinity());
    l.k_cut.push_back(k_cut);
    bool capped = false;
    const auto order = [&](double h) {
      const double needed = std::ceil(k_cut * h / (2.0 * pi)) + 1.0;
      if (!(needed <= o.max_alias_order)) {
        capped = true;
        return o.max_alias_order;
      }
      return static_cast<int>(needed);
    };
    const int px = order(l.dx), py = order(l.dy);
    if (reports) {
      (*reports)[d].alias_capped = capped;
      (*reports)[d].alias_order = std::max(px, py);
    }
    l.px = std::max(l.px, px);
    l.py = std::max(l.py, py);
  }
  l.hx = l.mx / 2 + 1;
  l.hy = l.my / 2 + 1;
  // Below Nyquist along both axes, every alias of a band wavevector is beyond the band.
  if (part == Part::long_range && band * l.dx < pi && band * l.dy < pi) {
    l.band = true;
    l.px = l.py = 0;
    l.hx = static_cast<std::ptrdiff_t>(band / l.dkx) + 1;
    l.hy = static_cast<std::ptrdiff_t>(band / l.dky) + 1;
  }
  return l;
}

// Refused beyond options.max_evaluations (or at z = 0), before any work; `estimate` the cost.
void refuse_costly(const Grid& grid, std::span<const double> depths, const StressKernelOptions& o,
                   double estimate) {
  const double z = *std::min_element(depths.begin(), depths.end());
  if (z == 0.0 || estimate > o.max_evaluations)
    throw InvalidArgument(detail::concat(
        "stress kernel: the plane at z = ", z, " m is so shallow against the domain (", grid.lx(),
        " x ", grid.ly(), " m) that its kernel needs about ", estimate, " FRF evaluations (limit ",
        o.max_evaluations, "): ask for deeper planes (the cost grows like (L/z)^2)"));
}

// The mode fields at k -> 0+: a wavenumber whose k h, k z and k L are all below 1e-10, where the
// fields differ from their limit by that relative amount (docs/theory.md 2.7).
std::vector<StressFrf> limit_at_zero(const LayerModes& modes, const Grid& grid,
                                     std::span<const double> depths, double thickness,
                                     InterfaceSide side) {
  const double scale =
      std::max({*std::max_element(depths.begin(), depths.end()), thickness, grid.lx(), grid.ly()});
  std::vector<StressFrf> limits;
  for (const ModeFields& m : modes.at(1e-10 / scale, depths, side))
    limits.push_back(stress_frf_at_zero(m));
  return limits;
}

using Sums = std::array<std::array<std::complex<double>, 3>, 6>;
using Quarters = std::array<std::array<Field, 3>, 6>;

// What the lattice loop reads: the body, the lattice, the planes and their k = 0 limits.
struct Sampling {
  const LayerModes& modes;
  const StressLattice& lattice;
  std::span<const double> depths;
  InterfaceSide side;
  int nb_loads;
  const std::vector<StressFrf>& at_zero;
};

// Adds the FRF times the cell transform at wavevector (kx, ky), weight w, into the sums of every
// plane whose cut-off it is within: one LayerModes solve for all of them.
void add_wavevector(const Sampling& s, double kx, double ky, double cell, std::vector<Sums>& acc,
                    std::vector<double>& active, std::vector<std::size_t>& index,
                    long long& evaluations) {
  const double k = std::hypot(kx, ky);
  const double w = cell * part_weight(s.lattice, k);
  if (k == 0.0) {
    for (std::size_t d = 0; d < acc.size(); ++d)
      for (int c = 0; c < 6; ++c)
        for (int ld = 0; ld < s.nb_loads; ++ld) acc[d][c][ld] += w * s.at_zero[d].stress[c][ld];
    return;
  }
  active.clear();
  index.clear();
  for (std::size_t d = 0; d < acc.size(); ++d)
    if (k <= s.lattice.k_cut[d]) {
      active.push_back(s.depths[d]);
      index.push_back(d);
    }
  if (active.empty()) return;
  const std::vector<ModeFields> fields = s.modes.at(k, active, s.side);
  ++evaluations;
  for (std::size_t a = 0; a < index.size(); ++a) {
    const StressFrf f = stress_frf(fields[a], kx / k, ky / k);
    for (int c = 0; c < 6; ++c)
      for (int ld = 0; ld < s.nb_loads; ++ld) acc[index[a]][c][ld] += w * f.stress[c][ld];
  }
}

// The real lattice quarters G = i^(odd_x + odd_y) F of every plane, component and load, F the
// alias-folded spectrum: real because each entry of T4 is real or imaginary with the parity of
// stress_frf_odd.
std::vector<Quarters> sample_quarters(const Sampling& s, int threads, long long& evaluations) {
  const StressLattice& l = s.lattice;
  const std::ptrdiff_t hx = l.hx;
  const std::ptrdiff_t hy = l.hy;
  std::vector<Quarters> g(s.depths.size());
  for (Quarters& q : g)
    for (int c = 0; c < 6; ++c)
      for (int ld = 0; ld < s.nb_loads; ++ld) q[c][ld] = Field::Zero(hx, hy);
  std::atomic<long long> count{0};
  // Wavevectors beyond every plane's cut-off add nothing (add_wavevector): skipped before their
  // sincs, window and radius are computed. Most aliases of a lattice point are beyond it; the
  // margin leaves the points at the cut-off itself to add_wavevector's own test.
  const double k_max = *std::max_element(l.k_cut.begin(), l.k_cut.end());
  const double beyond = k_max * k_max * (1.0 + 1e-12);
  detail::parallel_for(0, hy, threads, [&](std::ptrdiff_t jy) {
    long long local = 0;
    std::vector<Sums> acc(s.depths.size());
    std::vector<double> active;
    std::vector<std::size_t> index;
    for (std::ptrdiff_t jx = 0; jx < hx; ++jx) {
      // A row of a shallow plane's lattice folds thousands of aliases per point: seconds.
      check_interrupt();
      std::fill(acc.begin(), acc.end(), Sums{});
      for (int p = -l.px; p <= l.px; ++p) {
        const double kx = static_cast<double>(jx) * l.dkx + 2.0 * pi * p / l.dx;
        if (kx * kx > beyond) continue;
        const double wx = sinc(0.5 * kx * l.dx);
        for (int q = -l.py; q <= l.py; ++q) {
          const double ky = static_cast<double>(jy) * l.dky + 2.0 * pi * q / l.dy;
          if (kx * kx + ky * ky > beyond) continue;
          add_wavevector(s, kx, ky, wx * sinc(0.5 * ky * l.dy), acc, active, index, local);
        }
      }
      for (std::size_t d = 0; d < acc.size(); ++d)
        for (int c = 0; c < 6; ++c)
          for (int ld = 0; ld < s.nb_loads; ++ld) {
            const auto odd = stress_frf_odd(c, ld);
            std::complex<double> v = acc[d][c][ld];
            for (int n = 0; n < int(odd[0]) + int(odd[1]); ++n) v *= std::complex<double>(0, 1);
            g[d][c][ld](jx, jy) = v.real();
          }
    }
    count += local;
  });
  evaluations = count.load();
  return g;
}

}  // namespace

// The wavevectors |k| <= k_cut of the shallowest plane on DC-FFT's lattice with its aliases: a
// quarter disk of pi k_cut^2/4 over the lattice cell (2 pi/(2 lx)) (2 pi/(2 ly)), at least the
// lattice quarter; plus the long-range band, at most (34 alpha)^2.
double stress_kernel_evaluations(const Grid& grid, std::span<const double> depths,
                                 const StressKernelOptions& options) {
  validate(grid, depths, options);
  const double z = *std::min_element(depths.begin(), depths.end());
  if (z == 0.0) return std::numeric_limits<double>::infinity();
  return lattice_evaluations(grid, exponential_cut_off(z, options.tolerance), options.alpha);
}

std::vector<StressPlaneKernel> stress_plane_kernels(const Grid& grid, const LayerStack& stack,
                                                    std::span<const double> depths,
                                                    InterfaceSide side, bool tangential,
                                                    const StressKernelOptions& options,
                                                    std::vector<StressKernelReport>* reports) {
  const auto start = std::chrono::steady_clock::now();
  validate(grid, depths, options);
  std::vector<StressKernelReport> r(depths.size());
  const int nb_loads = tangential ? 3 : 1;
  const LayerModes modes(stack);
  const std::vector<StressFrf> at_zero =
      limit_at_zero(modes, grid, depths, stack.total_thickness(), side);
  std::vector<StressPlaneKernel> kernels(depths.size());
  for (std::size_t d = 0; d < depths.size(); ++d) {
    kernels[d].depth = depths[d];
    for (int c = 0; c < 6; ++c)
      for (int ld = 0; ld < nb_loads; ++ld)
        kernels[d].coefficients[c][ld] = Field::Zero(grid.nx(), grid.ny());
  }
  long long evaluations = 0;
  // K(x) = (1/(mx my)) sum_k F(k) exp(+i k.x) = (1/(mx my)) i^(ox + oy) T[F] = T[G]/(mx my),
  // T the parity transform: the coefficients are real.
  const auto add = [&](const StressLattice& l) {
    long long count = 0;
    const std::vector<Quarters> g =
        sample_quarters({modes, l, depths, side, nb_loads, at_zero}, options.threads, count);
    evaluations += count;
    const double scale = 1.0 / (static_cast<double>(l.mx) * static_cast<double>(l.my));
    for (std::size_t d = 0; d < depths.size(); ++d)
      for (int c = 0; c < 6; ++c)
        for (int ld = 0; ld < nb_loads; ++ld) {
          check_interrupt();  // each transform of the alpha-extended lattice takes a while
          const auto odd = stress_frf_odd(c, ld);
          if (l.band) {
            kernels[d].coefficients[c][ld] +=
                scale * band_parity_transform(g[d][c][ld], odd[0], odd[1], l.mx, l.my, grid.nx(),
                                              grid.ny());
          } else {
            const Field t = parity_transform(g[d][c][ld], odd[0], odd[1]);
            kernels[d].coefficients[c][ld] += scale * t.topLeftCorner(grid.nx(), grid.ny());
          }
        }
  };
  refuse_costly(grid, depths, options, stress_kernel_evaluations(grid, depths, options));
  if (options.alpha == 2) {
    add(make_lattice(grid, depths, options, 2, Part::whole, 0.0, &r));
  } else {
    // The short-range part on DC-FFT's own lattice (its images, >= L = 32 sigma away, are
    // negligible), the band-limited long-range part on the alpha-extended one.
    const double sigma = std::min(grid.lx(), grid.ly()) / 32.0;
    add(make_lattice(grid, depths, options, 2, Part::short_range, sigma, &r));
    add(make_lattice(grid, depths, options, options.alpha, Part::long_range, sigma, nullptr));
  }
  const double seconds = detail::seconds_since(start);
  for (StressKernelReport& x : r) {
    x.frf_evaluations = evaluations;
    x.seconds = seconds;
  }
  if (reports) *reports = r;
  return kernels;
}

double periodic_stress_evaluations(const Grid& grid, std::span<const double> depths,
                                   const StressKernelOptions& options) {
  validate(grid, depths, options);
  const double z = *std::min_element(depths.begin(), depths.end());
  if (z == 0.0) return std::numeric_limits<double>::infinity();
  const double k_cut = exponential_cut_off(z, options.tolerance);
  const double cell = (2.0 * pi / grid.lx()) * (2.0 * pi / grid.ly());
  const double quarter = (grid.nx() / 2 + 1.0) * (grid.ny() / 2 + 1.0);
  return std::max(0.25 * pi * k_cut * k_cut / cell, quarter);
}

std::vector<StressPlaneSpectrum> periodic_stress_spectra(const Grid& grid, const LayerStack& stack,
                                                         std::span<const double> depths,
                                                         InterfaceSide side, bool tangential,
                                                         const StressKernelOptions& options,
                                                         std::vector<StressKernelReport>* reports) {
  const auto start = std::chrono::steady_clock::now();
  validate(grid, depths, options);
  COATFFT_REQUIRE(grid.nx() % 2 == 0 && grid.ny() % 2 == 0,
                  "stress kernel: a periodic grid needs nx and ny even");
  refuse_costly(grid, depths, options, periodic_stress_evaluations(grid, depths, options));
  std::vector<StressKernelReport> r(depths.size());
  const int nb_loads = tangential ? 3 : 1;
  const LayerModes modes(stack);
  const std::vector<StressFrf> at_zero =
      limit_at_zero(modes, grid, depths, stack.total_thickness(), side);
  // The period's own lattice (alpha = 1): its quarters are the spectra themselves.
  const StressLattice lattice = make_lattice(grid, depths, options, 1, Part::whole, 0.0, &r);
  long long evaluations = 0;
  std::vector<Quarters> g = sample_quarters({modes, lattice, depths, side, nb_loads, at_zero},
                                            options.threads, evaluations);
  std::vector<StressPlaneSpectrum> spectra(depths.size());
  const double seconds = detail::seconds_since(start);
  for (std::size_t d = 0; d < depths.size(); ++d) {
    spectra[d].depth = depths[d];
    spectra[d].quarters = std::move(g[d]);
    r[d].frf_evaluations = evaluations;
    r[d].seconds = seconds;
  }
  if (reports) *reports = r;
  return spectra;
}

StressPlaneKernel stress_plane_kernel(const Grid& grid, const LayerStack& stack, double depth,
                                      InterfaceSide side, bool tangential,
                                      const StressKernelOptions& options,
                                      StressKernelReport* report) {
  std::vector<StressKernelReport> r;
  const double z[1] = {depth};
  StressPlaneKernel k = stress_plane_kernels(grid, stack, z, side, tangential, options, &r).front();
  if (report) *report = r.front();
  return k;
}

}  // namespace coatfft
