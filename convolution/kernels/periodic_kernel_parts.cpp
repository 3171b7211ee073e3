#include "convolution/kernels/detail/periodic_kernel_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "convolution/kernels/love_influence.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/sinc.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

namespace coatfft::detail {

namespace {

using std::numbers::pi;

// erf(alpha r)/r, smooth at r = 0 (its limit 2 alpha/sqrt(pi)).
double erf_over_r(double alpha, double r) {
  const double t = alpha * r;
  if (t < 1e-4) return 2.0 * alpha / std::sqrt(pi) * (1.0 - t * t / 3.0);
  return std::erf(t) / r;
}

// The wavenumber beyond which k H = Cinf to the tolerance over 8 doublings from 1e-3 of the
// lattice's step: the remainder R = H - Cinf/k is negligible beyond. 0 when it is negligible
// from the start (a homogeneous FRF).
double remainder_cut(const Grid& g, const Frf& frf, double tolerance) {
  const double c = frf.c_inf();
  double k = 1e-3 * 2.0 * pi / std::max(g.lx(), g.ly());
  int run = 0;
  double start = 0.0;
  for (int n = 0; n < 400; ++n, k *= 2.0) {
    if (std::abs(k * frf(k) - c) <= tolerance * c) {
      if (run++ == 0) start = k;
      if (run == 8) return n == 7 ? 0.0 : start;
    } else {
      run = 0;
    }
  }
  throw InvalidArgument("periodic kernel: k H(k) of the FRF does not approach its c_inf()");
}

void validate(const Grid& g, const Frf& frf, const PeriodicKernelOptions& o) {
  COATFFT_REQUIRE(g.nx() % 2 == 0 && g.ny() % 2 == 0, "periodic kernel: nx = ", g.nx(),
                  " and ny = ", g.ny(), " must be even");
  COATFFT_REQUIRE(o.tolerance > 0 && o.tolerance <= 1e-6,
                  "periodic kernel: tolerance must be in (0, 1e-6]");
  COATFFT_REQUIRE(o.threads >= 1 && o.threads <= max_threads,
                  "periodic kernel: threads must be in [1, ", max_threads, "]");
  COATFFT_REQUIRE(std::isfinite(frf.c_inf()) && frf.c_inf() > 0,
                  "periodic kernel: the FRF's c_inf() must be finite and > 0");
}

EwaldLattice make_lattice(const Grid& g, const Frf& frf, double alpha,
                          const PeriodicKernelOptions& o) {
  validate(g, frf, o);
  const EwaldLattice l = ewald_lattice(g, alpha, remainder_cut(g, frf, o.tolerance));
  const double k_max = std::max(l.k_ewald, l.k_rest);
  // The points of the aliased half lattice within k_max: the aliases tile the plane, so about half
  // a disk of lattice cells (the loop visits every alias too, but a visit outside costs a compare).
  const double evaluations = 0.5 * pi * (k_max / l.dkx + 2.0) * (k_max / l.dky + 2.0);
  COATFFT_REQUIRE(evaluations <= o.max_evaluations,
                  "periodic kernel: the FRF's remainder reaches k = ", brief(k_max),
                  " rad/m, so far against the cells that about ", brief(evaluations),
                  " evaluations are needed (limit ", brief(o.max_evaluations), ")");
  return l;
}

}  // namespace

ErfOverR::ErfOverR(double alpha, double r_max)
    : alpha_(alpha), step_(5e-4 / (alpha * alpha)), inverse_step_(1.0 / step_) {
  // An elongated period (alpha from its short side) would need a table of its long side in steps
  // of the short one: beyond a million values (8 MB) the function is evaluated directly.
  const double count = r_max * r_max / step_ + 4;
  if (count > 1e6) return;
  const auto n = static_cast<std::size_t>(count);
  values_.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    values_[k] = erf_over_r(alpha, std::sqrt(static_cast<double>(k) * step_));
}

double ErfOverR::operator()(double s) const {
  const double u = s * inverse_step_;
  const auto k = static_cast<std::size_t>(u);
  // The first interval (no point left of it) and beyond the table: directly.
  if (k < 1 || k + 2 >= values_.size()) return erf_over_r(alpha_, std::sqrt(s));
  const double t = u - static_cast<double>(k);
  const double* v = values_.data() + k - 1;
  // Lagrange's cubic through the points k - 1, k, k + 1, k + 2 at k + t.
  return -t * (t - 1) * (t - 2) / 6 * v[0] + (t + 1) * (t - 1) * (t - 2) / 2 * v[1] -
         (t + 1) * t * (t - 2) / 2 * v[2] + (t + 1) * t * (t - 1) / 6 * v[3];
}

PeriodicKernelParts::PeriodicKernelParts(const Grid& grid, const Frf& frf,
                                         const PeriodicKernelOptions& options)
    : grid_(grid),
      frf_(frf),
      alpha_(ewald_alpha(grid)),
      lattice_(make_lattice(grid, frf, alpha_, options)),
      // The farthest point of the 3 x 3 images' cells: 1.5 periods and a cell along each axis.
      erf_over_r_(alpha_, std::hypot(1.5 * grid.lx() + grid.dx(), 1.5 * grid.ly() + grid.dy())) {}

double PeriodicKernelParts::spectrum(std::ptrdiff_t i, std::ptrdiff_t j) const {
  const Grid& g = grid_;
  const EwaldLattice& l = lattice_;
  const double c = frf_.c_inf();
  const double sj = static_cast<double>(j <= l.ny / 2 ? j : j - l.ny);
  double sum = 0.0;
  for (int p = -l.px; p <= l.px; ++p)
    for (int q = -l.py; q <= l.py; ++q) {
      const double kx = static_cast<double>(i) * l.dkx + 2.0 * pi * p / g.dx();
      const double ky = sj * l.dky + 2.0 * pi * q / g.dy();
      const double k = std::sqrt(kx * kx + ky * ky);  // no overflow: k is of order 1 / dx
      if (k == 0.0 || k > std::max(l.k_ewald, l.k_rest)) continue;
      const double s = sinc(0.5 * kx * g.dx()) * sinc(0.5 * ky * g.dy());
      double h = 0.0;
      if (k <= l.k_ewald) h += c * std::erfc(k / (2.0 * alpha_)) / k;
      if (k <= l.k_rest) h += frf_(k) - c / k;
      sum += h * s;
    }
  return sum;
}

// Per unit C: the cell integral of erfc(alpha R)/(2 pi R) summed over the 3 x 3 nearest images
// of the offset folded into |x| <= lx/2, |y| <= ly/2 (the next images are >= 1.5 min(lx, ly) =
// 9/alpha away: erfc(9) = 4e-37). Love's cell integral of 1/(pi R) (E* = 1) is twice that of
// 1/(2 pi R); the smooth erf(alpha R)/(2 pi R) is entire.
double PeriodicKernelParts::real_space(std::ptrdiff_t i, std::ptrdiff_t j) const {
  const Grid& g = grid_;
  const double x = static_cast<double>(i <= g.nx() / 2 ? i : g.nx() - i) * g.dx();
  const double y = static_cast<double>(j <= g.ny() / 2 ? j : g.ny() - j) * g.dy();
  const double alpha = alpha_;
  const auto smooth = [this](double u, double v) {
    return erf_over_r_(u * u + v * v) / (2.0 * pi);
  };
  // An image whose cell lies beyond kEwaldErfcCut / alpha adds erfc(6.5) = 3.8e-20 of its 1/R
  // (the two integrals below cancel to their rounding): skipped. With x, y >= 0 that is every
  // image at +lx or +ly but those of offsets within 0.08 of a period from an axis.
  const double reach = kEwaldErfcCut / alpha;
  double sum = 0.0;
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) {
      const double X = x + a * g.lx(), Y = y + b * g.ly();
      if (std::hypot(std::max(std::abs(X) - 0.5 * g.dx(), 0.0),
                     std::max(std::abs(Y) - 0.5 * g.dy(), 0.0)) >= reach)
        continue;
      sum += 0.5 * love_influence(X, Y, g.dx(), g.dy()) -
             smooth_cell_integral(smooth, alpha, X, Y, g.dx(), g.dy());
    }
  return frf_.c_inf() * sum;
}

}  // namespace coatfft::detail
