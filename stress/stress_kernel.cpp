#include "stress/stress_kernel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "frf/stress_frf.hpp"
#include "stress/parity_transform.hpp"

namespace coatfft {

namespace {

constexpr double kPi = 3.14159265358979323846;

double sinc(double x) {
  return std::abs(x) < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x;
}

// The sampling lattice: (mx, my) = alpha (nx, ny) points of spacing (dx, dy), wavenumber steps
// 2 pi / (mx dx); aliases p 2 pi / dx up to order (px, py); FRF terms beyond |k| > k_cut dropped.
struct Lattice {
  std::ptrdiff_t mx, my;
  double dx, dy, dkx, dky;
  double k_cut;
  int px, py;
};

void validate(const Grid& grid, double depth, const StressKernelOptions& o) {
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
Lattice make_lattice(const Grid& grid, double depth, const StressKernelOptions& o,
                     StressKernelReport& report) {
  Lattice l{};
  l.mx = o.alpha * grid.nx();
  l.my = o.alpha * grid.ny();
  l.dx = grid.dx();
  l.dy = grid.dy();
  l.dkx = 2.0 * kPi / (static_cast<double>(l.mx) * l.dx);
  l.dky = 2.0 * kPi / (static_cast<double>(l.my) * l.dy);
  const double log_tol = std::log(1.0 / o.tolerance);
  l.k_cut = depth > 0.0 ? (log_tol + 2.0 * std::log1p(log_tol) + 3.0) / depth
                        : std::numeric_limits<double>::infinity();
  const auto order = [&](double d) {
    const double needed = std::ceil(l.k_cut * d / (2.0 * kPi)) + 1.0;
    if (!(needed <= o.max_alias_order)) {
      report.alias_capped = true;
      return o.max_alias_order;
    }
    return static_cast<int>(needed);
  };
  l.px = order(l.dx);
  l.py = order(l.dy);
  report.alias_order = std::max(l.px, l.py);
  return l;
}

// The mode fields at k -> 0+: a wavenumber whose k h, k z and k L are all below 1e-10, where the
// fields differ from their limit by that relative amount (docs/theory.md 2.7).
StressFrf limit_at_zero(const LayerModes& modes, const Grid& grid, double depth, double thickness,
                        InterfaceSide side) {
  const double scale = std::max({depth, thickness, grid.lx(), grid.ly()});
  const double k0 = 1e-10 / scale;
  const double z[1] = {depth};
  return stress_frf_at_zero(modes.at(k0, z, side).front());
}

using Quarters = std::array<std::array<Field, 3>, 6>;

// Adds the alias-folded FRF times the cell transform at lattice point (jx, jy) into `acc`.
void fold_point(const LayerModes& modes, const Lattice& l, double depth, InterfaceSide side,
                int nb_loads, const StressFrf& at_zero, std::ptrdiff_t jx, std::ptrdiff_t jy,
                std::array<std::array<std::complex<double>, 3>, 6>& acc, long long& evaluations) {
  const double z[1] = {depth};
  for (int p = -l.px; p <= l.px; ++p) {
    const double kx = static_cast<double>(jx) * l.dkx + 2.0 * kPi * p / l.dx;
    const double wx = sinc(0.5 * kx * l.dx);
    for (int q = -l.py; q <= l.py; ++q) {
      const double ky = static_cast<double>(jy) * l.dky + 2.0 * kPi * q / l.dy;
      const double k = std::hypot(kx, ky);
      if (k > l.k_cut) continue;
      const double w = wx * sinc(0.5 * ky * l.dy);
      StressFrf f;
      if (k == 0.0) {
        f = at_zero;
      } else {
        f = stress_frf(modes.at(k, z, side).front(), kx / k, ky / k);
        ++evaluations;
      }
      for (int c = 0; c < 6; ++c)
        for (int ld = 0; ld < nb_loads; ++ld) acc[c][ld] += w * f.stress[c][ld];
    }
  }
}

// The real lattice quarters G = i^(odd_x + odd_y) F of every (component, load), F the folded
// spectrum: real because each entry of T4 is real or imaginary with the parity of stress_frf_odd.
Quarters sample_quarters(const LayerModes& modes, const Lattice& l, double depth,
                         InterfaceSide side, int nb_loads, const StressFrf& at_zero, int threads,
                         long long& evaluations) {
  const std::ptrdiff_t hx = l.mx / 2 + 1;
  const std::ptrdiff_t hy = l.my / 2 + 1;
  Quarters g;
  for (int c = 0; c < 6; ++c)
    for (int ld = 0; ld < nb_loads; ++ld) g[c][ld] = Field::Zero(hx, hy);
  std::atomic<long long> count{0};
  detail::parallel_for(0, hy, threads, [&](std::ptrdiff_t jy) {
    long long local = 0;
    for (std::ptrdiff_t jx = 0; jx < hx; ++jx) {
      std::array<std::array<std::complex<double>, 3>, 6> acc{};
      fold_point(modes, l, depth, side, nb_loads, at_zero, jx, jy, acc, local);
      for (int c = 0; c < 6; ++c)
        for (int ld = 0; ld < nb_loads; ++ld) {
          const auto odd = stress_frf_odd(c, ld);
          std::complex<double> v = acc[c][ld];
          for (int n = 0; n < int(odd[0]) + int(odd[1]); ++n) v *= std::complex<double>(0.0, 1.0);
          g[c][ld](jx, jy) = v.real();
        }
    }
    count += local;
  });
  evaluations = count.load();
  return g;
}

}  // namespace

StressPlaneKernel stress_plane_kernel(const Grid& grid, const LayerStack& stack, double depth,
                                      InterfaceSide side, bool tangential,
                                      const StressKernelOptions& options,
                                      StressKernelReport* report) {
  const auto start = std::chrono::steady_clock::now();
  validate(grid, depth, options);
  StressKernelReport r;
  const Lattice l = make_lattice(grid, depth, options, r);
  const int nb_loads = tangential ? 3 : 1;
  const LayerModes modes(stack);
  const StressFrf at_zero = limit_at_zero(modes, grid, depth, stack.total_thickness(), side);
  const Quarters g =
      sample_quarters(modes, l, depth, side, nb_loads, at_zero, options.threads, r.frf_evaluations);

  // K(x) = (1/(mx my)) sum_k F(k) exp(+i k.x) = (1/(mx my)) i^(ox + oy) T[F] = T[G]/(mx my),
  // T the parity transform: the coefficients are real.
  StressPlaneKernel kernel;
  kernel.depth = depth;
  const double scale = 1.0 / (static_cast<double>(l.mx) * static_cast<double>(l.my));
  for (int c = 0; c < 6; ++c)
    for (int ld = 0; ld < nb_loads; ++ld) {
      const auto odd = stress_frf_odd(c, ld);
      const Field t = parity_transform(g[c][ld], odd[0], odd[1]);
      kernel.coefficients[c][ld] = scale * t.topLeftCorner(grid.nx(), grid.ny());
    }
  r.seconds = detail::seconds_since(start);
  if (report) *report = r;
  return kernel;
}

}  // namespace coatfft
