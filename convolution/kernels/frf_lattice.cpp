#include "convolution/kernels/detail/frf_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "core/detail/parallel_for.hpp"
#include "core/error.hpp"

namespace coatfft {

std::ptrdiff_t extended_size(std::ptrdiff_t n, double alpha, double min_alpha, const char* who) {
  COATFFT_REQUIRE(std::isfinite(alpha) && alpha >= min_alpha, who, ": alpha = ", alpha,
                  ", but the domain extension ratio must be finite and >= ", min_alpha);
  const double m = alpha * static_cast<double>(n);
  const double rounded = std::round(m);
  COATFFT_REQUIRE(std::abs(m - rounded) <= 1e-9 * m, who, ": alpha * n = ", alpha, " * ", n, " = ",
                  m,
                  " is not an integer; choose alpha so that alpha * nx and alpha * ny are "
                  "whole numbers of cells");
  return static_cast<std::ptrdiff_t>(rounded);
}

G0Result lattice_g0(const Grid& grid, const Frf& frf, double alpha, double min_alpha,
                    G0Method method, double tolerance, const char* who) {
  using std::numbers::pi;
  const auto mx = static_cast<double>(extended_size(grid.nx(), alpha, min_alpha, who));
  const auto my = static_cast<double>(extended_size(grid.ny(), alpha, min_alpha, who));
  return compute_g0(frf, 2.0 * pi / (mx * grid.dx()), 2.0 * pi / (my * grid.dy()), method,
                    tolerance);
}

namespace detail {

Field sample_frf_quarter(const Frf& frf, std::ptrdiff_t qx, std::ptrdiff_t qy, double dkx,
                         double dky, int threads) {
  COATFFT_REQUIRE(threads >= 1, "sample_frf_quarter: threads = ", threads, ", but must be >= 1");
  // H is radial: on a square lattice (dkx == dky, exactly: same period and cell) the sample at
  // (jx, jy) equals the one at (jy, jx), so only jy <= jx is evaluated (half the FRF calls) and
  // the rest is copied. FRF evaluations dominate the cost (exp, expm1, sinh per call for a
  // coating), so the lower triangle is the work; it is shared by interleaved columns.
  // Each column's samples are one Frf::evaluate batch, written straight into the column (x is
  // contiguous in a Field): one call per column for an FRF with a cost per call.
  const bool swap = dkx == dky;
  Field q(qx, qy);
  const auto column = [&](std::ptrdiff_t jy) {
    const double ky = dky * static_cast<double>(jy);
    // k = 0 is singular (H ~ C0/k): that entry is left 0 for the caller's g(0).
    // Rows jx < jy are mirrored from column jx, row jy: possible only where jy < qx.
    const std::ptrdiff_t first = std::max<std::ptrdiff_t>(swap && jy < qx ? jy : 0, jy == 0);
    if (jy == 0 && qx > 0) q(0, 0) = 0.0;
    if (first >= qx) return;
    std::vector<double> k(static_cast<std::size_t>(qx - first));
    for (std::ptrdiff_t jx = first; jx < qx; ++jx)
      k[static_cast<std::size_t>(jx - first)] = std::hypot(dkx * static_cast<double>(jx), ky);
    frf.evaluate(k, std::span<double>(&q(first, jy), k.size()));
  };
  // An FRF refusing a wavenumber throws in a worker: parallel_for rethrows it here.
  detail::parallel_for(0, qy, threads, column);
  if (swap)
    for (std::ptrdiff_t jy = 1; jy < std::min(qy, qx); ++jy)
      for (std::ptrdiff_t jx = 0; jx < jy; ++jx) q(jx, jy) = q(jy, jx);
  return q;
}

}  // namespace detail

Field sample_frf_half_spectrum(const Frf& frf, std::ptrdiff_t mx, std::ptrdiff_t my, double dx,
                               double dy, double g0, int threads) {
  using std::numbers::pi;
  const std::ptrdiff_t hx = mx / 2 + 1;
  const double dkx = 2.0 * pi / (static_cast<double>(mx) * dx);
  const double dky = 2.0 * pi / (static_cast<double>(my) * dy);
  // Wrap-around order along y: 0..ceil(my/2)-1, then -floor(my/2)..-1. H is radial, so only |ky|
  // matters (and the Nyquist row of an even my is the same for either sign): the samples are
  // those of the quarter |jy| <= my/2, mirrored, which halves the FRF evaluations (again on a
  // square lattice, see sample_frf_quarter).
  const Field q = detail::sample_frf_quarter(frf, hx, my / 2 + 1, dkx, dky, threads);
  Field h(hx, my);
  for (std::ptrdiff_t jy = 0; jy < my; ++jy) {
    h.col(jy) = q.col(detail::folded_index(jy, my));
  }
  h(0, 0) = g0;
  return h;
}

}  // namespace coatfft
