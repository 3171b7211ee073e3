#include "convolution/kernels/periodic_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "convolution/fft/fftw_plan.hpp"
#include "convolution/kernels/ewald.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/sinc.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

namespace coatfft {

namespace {

using detail::EwaldLattice;
using std::numbers::pi;

using detail::sinc;

// erf(alpha r)/r, smooth at r = 0 (its limit 2 alpha/sqrt(pi)).
double erf_over_r(double alpha, double r) {
  const double t = alpha * r;
  if (t < 1e-4) return 2.0 * alpha / std::sqrt(pi) * (1.0 - t * t / 3.0);
  return std::erf(t) / r;
}

// The Ewald split's real-space part, per unit C: the cell integral of erfc(alpha R)/(2 pi R)
// summed over the 3 x 3 nearest images of the offset (x, y), |x| <= lx/2, |y| <= ly/2 (the next
// images are >= 1.5 min(lx, ly) = 9/alpha away: erfc(9) = 4e-37). Love's cell integral of 1/(pi R)
// (E* = 1) is twice that of 1/(2 pi R); the smooth erf(alpha R)/(2 pi R) is entire.
double real_space(const Grid& g, double alpha, double x, double y) {
  const auto smooth = [alpha](double u, double v) {
    return erf_over_r(alpha, std::hypot(u, v)) / (2.0 * pi);
  };
  double sum = 0.0;
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) {
      const double X = x + a * g.lx(), Y = y + b * g.ly();
      sum += 0.5 * love_influence(X, Y, g.dx(), g.dy()) -
             detail::smooth_cell_integral(smooth, alpha, X, Y, g.dx(), g.dy());
    }
  return sum;
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

// The spectrum M(i, j) = sum over the aliases of (C erfc(k/(2 alpha))/k + R(k)) S(k), k != 0, on
// the half lattice 0 <= i <= nx/2 (FFTW's c2r layout, j the signed frequency).
std::vector<double> spectrum(const Grid& g, const Frf& frf, const EwaldLattice& l, double alpha,
                             int threads) {
  const double c = frf.c_inf();
  std::vector<double> m(static_cast<std::size_t>(l.hx * l.ny), 0.0);
  detail::parallel_for(0, l.ny, threads, [&](std::ptrdiff_t j) {
    const double sj = static_cast<double>(j <= l.ny / 2 ? j : j - l.ny);
    for (std::ptrdiff_t i = 0; i < l.hx; ++i) {
      double sum = 0.0;
      for (int p = -l.px; p <= l.px; ++p)
        for (int q = -l.py; q <= l.py; ++q) {
          const double kx = i * l.dkx + 2.0 * pi * p / g.dx();
          const double ky = sj * l.dky + 2.0 * pi * q / g.dy();
          const double k = std::hypot(kx, ky);
          if (k == 0.0 || k > std::max(l.k_ewald, l.k_rest)) continue;
          const double s = sinc(0.5 * kx * g.dx()) * sinc(0.5 * ky * g.dy());
          double h = 0.0;
          if (k <= l.k_ewald) h += c * std::erfc(k / (2.0 * alpha)) / k;
          if (k <= l.k_rest) h += frf(k) - c / k;
          sum += h * s;
        }
      m[static_cast<std::size_t>(j * l.hx + i)] = sum;
    }
  });
  return m;
}

// K_F(i, j) = (1/(nx ny)) sum_m M_m exp(i k_m . d) over the whole lattice (M real and even).
Field to_space(const Grid& g, const std::vector<double>& m) {
  const std::ptrdiff_t hx = g.nx() / 2 + 1;
  FftwComplexBuffer in(static_cast<std::size_t>(hx * g.ny()));
  for (std::size_t n = 0; n < m.size(); ++n) as_complex(in.data())[n] = m[n];
  FftwRealBuffer out(static_cast<std::size_t>(g.nx() * g.ny()));
  const FftwPlan plan = FftwPlan::create(1, [&] {
    return fftw_plan_dft_c2r_2d(int(g.ny()), int(g.nx()), in.data(), out.data(),
                                FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
  plan.execute();
  return Eigen::Map<const Field>(out.data(), g.nx(), g.ny()) / double(g.nx() * g.ny());
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
  const EwaldLattice l = detail::ewald_lattice(g, alpha, remainder_cut(g, frf, o.tolerance));
  const double k_max = std::max(l.k_ewald, l.k_rest);
  // The points of the aliased half lattice within k_max: the aliases tile the plane, so about half
  // a disk of lattice cells (the loop visits every alias too, but a visit outside costs a compare).
  const double evaluations = 0.5 * pi * (k_max / l.dkx + 2.0) * (k_max / l.dky + 2.0);
  COATFFT_REQUIRE(evaluations <= o.max_evaluations,
                  "periodic kernel: the FRF's remainder reaches k = ", detail::brief(k_max),
                  " rad/m, so far against the cells that about ", detail::brief(evaluations),
                  " evaluations are needed (limit ", detail::brief(o.max_evaluations), ")");
  return l;
}

}  // namespace

Field periodic_influence_kernel(const Grid& g, const Frf& frf, const PeriodicKernelOptions& o) {
  validate(g, frf, o);
  const double alpha = detail::ewald_alpha(g);
  const EwaldLattice l = make_lattice(g, frf, alpha, o);
  Field k = to_space(g, spectrum(g, frf, l, alpha, o.threads));
  const double c = frf.c_inf();
  const std::ptrdiff_t hx = g.nx() / 2, hy = g.ny() / 2;
  Field quarter(hx + 1, hy + 1);
  detail::parallel_for(0, hy + 1, o.threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = 0; i <= hx; ++i)
      quarter(i, j) = c * real_space(g, alpha, i * g.dx(), j * g.dy());
  });
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
      k(i, j) += quarter(i <= hx ? i : g.nx() - i, j <= hy ? j : g.ny() - j);
  // The k = 0 term is left out: the real-space part's integral over the plane is removed with the
  // mean (the lattice part has none: every alias of k = 0 has S = 0).
  return k - k.mean();
}

}  // namespace coatfft
