#include "convolution/kernels/periodic_traction_kernels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/angular_influence.hpp"
#include "convolution/kernels/detail/ewald.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/sinc.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/threads.hpp"
#include "frf/frf.hpp"
#include "frf/traction_response.hpp"

namespace coatfft {

namespace {

using detail::EwaldLattice;
using std::numbers::pi;

// The four angular kernels, in the order of their FRFs cos 2theta, sin 2theta, -i cos theta,
// -i sin theta (each per unit coefficient: 1/k times it).
using Angular = std::array<double, 4>;
constexpr std::array<std::array<bool, 2>, 4> kOdd{
    {{false, false}, {true, true}, {true, false}, {false, true}}};

// (f'' - f'/r)/r^2 for f = r erf(alpha r), smooth (its series below alpha r = 1e-2, where the
// next term is 1e-8 of it); for f = r it is -1/r^3, the factor of the full kernels
// (y^2 - x^2)/(2 pi r^3) and -x y/(pi r^3).
double smooth_g(double alpha, double r) {
  const double t = alpha * r;
  if (t < 1e-2) return 4.0 * alpha * alpha * alpha / std::sqrt(pi) * (-4.0 / 3.0 + 1.2 * t * t);
  const double e = std::exp(-t * t);
  const double fp = std::erf(t) + 2.0 * t / std::sqrt(pi) * e;
  const double fpp = 4.0 * alpha / std::sqrt(pi) * e * (1.0 - t * t);
  return (fpp - fp / r) / (r * r);
}

// (1 - exp(-alpha^2 r^2))/r^2: the smooth counterpart of 1/r^2 in x/(2 pi r^2), the kernel of
// -i cos theta/k (d_x of ln r + E1(alpha^2 r^2)/2).
double smooth_h(double alpha, double r) {
  const double t = alpha * r;
  return t < 1e-8 ? alpha * alpha : -std::expm1(-t * t) / (r * r);
}

// The short-range parts at the offset (x, y), summed over the 3 x 3 nearest images (the next
// are >= 1.5 min(lx, ly) = 9/alpha away): the closed-form cell integrals of the full kernels
// (angular_influence at beta = 0) less those of the smooth ones.
Angular short_range(const Grid& g, double alpha, double x, double y) {
  const auto s_cos2 = [alpha](double u, double v) {
    return (u * u - v * v) / (2.0 * pi) * smooth_g(alpha, std::hypot(u, v));
  };
  const auto s_sin2 = [alpha](double u, double v) {
    return u * v / pi * smooth_g(alpha, std::hypot(u, v));
  };
  const auto s_cos1 = [alpha](double u, double v) {
    return u / (2.0 * pi) * smooth_h(alpha, std::hypot(u, v));
  };
  const auto s_sin1 = [alpha](double u, double v) {
    return v / (2.0 * pi) * smooth_h(alpha, std::hypot(u, v));
  };
  Angular sum{};
  const double dx = g.dx(), dy = g.dy();
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) {
      const double X = x + a * g.lx(), Y = y + b * g.ly();
      const AngularCoefficients full = angular_influence(X, Y, dx, dy, 0.0);
      const double full_sin1 = angular_influence(Y, X, dy, dx, 0.0).cos1;
      sum[0] += full.cos2 - detail::smooth_cell_integral(s_cos2, alpha, X, Y, dx, dy);
      sum[1] += full.sin2 - detail::smooth_cell_integral(s_sin2, alpha, X, Y, dx, dy);
      sum[2] += full.cos1 - detail::smooth_cell_integral(s_cos1, alpha, X, Y, dx, dy);
      sum[3] += full_sin1 - detail::smooth_cell_integral(s_sin1, alpha, X, Y, dx, dy);
    }
  return sum;
}

// The wavenumber beyond which k D(k) and k C(k) are their top medium's values to the tolerance
// (of k S's, which is > 0) over 8 doublings: the remainders are negligible beyond. 0 for a
// homogeneous body.
double remainder_cut(const Grid& g, const TractionResponse& r, double tolerance) {
  const TractionFrfs& inf = r.at_infinity();
  double k = 1e-3 * 2.0 * pi / std::max(g.lx(), g.ly());
  for (int n = 0, run = 0; n < 400; ++n, k *= 2.0) {
    const TractionFrfs f = r(k);
    const bool small = std::abs(k * f.d - inf.d) <= tolerance * inf.s &&
                       std::abs(k * f.c - inf.c) <= tolerance * inf.s;
    run = small ? run + 1 : 0;
    if (run == 8) return n == 7 ? 0.0 : k / 128.0;
  }
  throw InvalidArgument("periodic traction kernels: k D(k), k C(k) do not approach their limits");
}

// The aliased lattice points within the remainders' reach k_rest: about half a disk of lattice
// cells (as periodic_influence_kernel's).
double remainder_evaluations(const Grid& g, double k_rest) {
  if (k_rest == 0.0) return 0.0;
  return 0.5 * pi * (k_rest * g.lx() / (2.0 * pi) + 2.0) * (k_rest * g.ly() / (2.0 * pi) + 2.0);
}

TractionResponse bonded_response(const LayerStack& stack) {
  TractionResponse response(stack);
  COATFFT_REQUIRE(response.bonded(),
                  "periodic traction kernels: tangential tractions need every interface bonded (a "
                  "coating over a frictionless interface has no equilibrium under a net "
                  "tangential force)");
  return response;
}

EwaldLattice make_lattice(const Grid& g, const TractionResponse& r, double alpha,
                          const PeriodicKernelOptions& o) {
  const EwaldLattice l = detail::ewald_lattice(g, alpha, remainder_cut(g, r, o.tolerance));
  const double evaluations = remainder_evaluations(g, l.k_rest);
  COATFFT_REQUIRE(evaluations <= o.max_evaluations,
                  "periodic traction kernels: the remainders reach k = ", detail::brief(l.k_rest),
                  " rad/m, so far against the cells that about ", detail::brief(evaluations),
                  " FRF evaluations are needed (limit ", detail::brief(o.max_evaluations), ")");
  return l;
}

// The lattice parts' spectra at (kx, ky), k = |k| > 0, times the cell's transform `cell`: the
// Gaussian-fast complements of the short-range parts, with the top medium's D and C, and the
// remainders; `sums` in the order of Angular.
void add_wavevector(const TractionResponse& r, const EwaldLattice& l, double alpha, double kx,
                    double ky, double k, double cell, std::array<std::complex<double>, 4>& sums) {
  const TractionFrfs& inf = r.at_infinity();
  const std::complex<double> i(0.0, 1.0);
  if (k <= l.k_ewald) {
    // The transform of r erf(alpha r), whose derivatives d_xx - d_yy, d_xy multiply it by
    // -(kx^2 - ky^2), -kx ky; of ln r + E1(alpha^2 r^2)/2, -2 pi exp(-k^2/(4 alpha^2))/k^2.
    const double gauss = std::exp(-k * k / (4.0 * alpha * alpha));
    const double f =
        -2.0 * pi / (k * k * k) * std::erfc(k / (2.0 * alpha)) -
        2.0 * std::sqrt(pi) / (alpha * k * k) * gauss * (1.0 + k * k / (2.0 * alpha * alpha));
    sums[0] += inf.d * cell * (ky * ky - kx * kx) * f / (2.0 * pi);
    sums[1] += inf.d * cell * (-kx * ky) * f / pi;
    sums[2] += inf.c * cell * (-i) * kx * gauss / (k * k);
    sums[3] += inf.c * cell * (-i) * ky * gauss / (k * k);
  }
  if (k <= l.k_rest) {
    const TractionFrfs x = r(k);
    const double rd = x.d - inf.d / k, rc = x.c - inf.c / k, c = kx / k, s = ky / k;
    sums[0] += rd * cell * (c * c - s * s);
    sums[1] += rd * cell * 2.0 * c * s;
    sums[2] += rc * cell * (-i) * c;
    sums[3] += rc * cell * (-i) * s;
  }
}

// The four lattice parts in space: K(d) = (1/(nx ny)) sum over the lattice of F exp(i k.d).
std::array<Field, 4> lattice_part(const Grid& g, const TractionResponse& r, const EwaldLattice& l,
                                  double alpha, int threads) {
  std::array<std::vector<std::complex<double>>, 4> spectra;
  for (auto& s : spectra) s.assign(static_cast<std::size_t>(l.hx * l.ny), 0.0);
  const double k_max = std::max(l.k_ewald, l.k_rest);
  detail::parallel_for(0, l.ny, threads, [&](std::ptrdiff_t j) {
    check_interrupt();
    const double sj = static_cast<double>(j <= l.ny / 2 ? j : j - l.ny);
    for (std::ptrdiff_t i = 0; i < l.hx; ++i) {
      std::array<std::complex<double>, 4> sums{};
      for (int p = -l.px; p <= l.px; ++p)
        for (int q = -l.py; q <= l.py; ++q) {
          const double kx = i * l.dkx + 2.0 * pi * p / g.dx();
          const double ky = sj * l.dky + 2.0 * pi * q / g.dy();
          const double k = std::hypot(kx, ky);
          if (k == 0.0 || k > k_max) continue;
          const double cell = detail::sinc(0.5 * kx * g.dx()) * detail::sinc(0.5 * ky * g.dy());
          add_wavevector(r, l, alpha, kx, ky, k, cell, sums);
        }
      for (int c = 0; c < 4; ++c) spectra[c][static_cast<std::size_t>(j * l.hx + i)] = sums[c];
    }
  });
  std::array<Field, 4> out;
  FftwComplexBuffer in(static_cast<std::size_t>(l.hx * l.ny));
  FftwRealBuffer space(static_cast<std::size_t>(g.nx() * g.ny()));
  const FftwPlan plan = FftwPlan::create(1, [&] {
    return fftw_plan_dft_c2r_2d(int(g.ny()), int(g.nx()), in.data(), space.data(),
                                FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
  for (int c = 0; c < 4; ++c) {
    std::copy(spectra[c].begin(), spectra[c].end(), as_complex(in.data()));
    plan.execute();
    out[c] = Eigen::Map<const Field>(space.data(), g.nx(), g.ny()) / double(g.nx() * g.ny());
  }
  return out;
}

// The short-range parts on the quarter 0 <= i <= nx/2, 0 <= j <= ny/2, added to `k` with the
// parities, times the top medium's D (cos 2theta, sin 2theta) and C (the others).
void add_short_range(const Grid& g, const TractionFrfs& inf, double alpha, int threads,
                     std::array<Field, 4>& k) {
  const std::ptrdiff_t hx = g.nx() / 2, hy = g.ny() / 2;
  std::vector<Angular> quarter(static_cast<std::size_t>((hx + 1) * (hy + 1)));
  detail::parallel_for(0, hy + 1, threads, [&](std::ptrdiff_t j) {
    check_interrupt();
    for (std::ptrdiff_t i = 0; i <= hx; ++i)
      quarter[static_cast<std::size_t>(j * (hx + 1) + i)] =
          short_range(g, alpha, i * g.dx(), j * g.dy());
  });
  const std::array<double, 4> scale{inf.d, inf.d, inf.c, inf.c};
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
      const bool mx = i > hx, my = j > hy;
      const Angular& v = quarter[static_cast<std::size_t>((my ? g.ny() - j : j) * (hx + 1) +
                                                          (mx ? g.nx() - i : i))];
      for (int c = 0; c < 4; ++c) {
        const double sign = ((mx && kOdd[c][0]) != (my && kOdd[c][1])) ? -1.0 : 1.0;
        k[c](i, j) += sign * scale[c] * v[c];
      }
    }
}

}  // namespace

TractionKernels periodic_traction_kernels(const Grid& g, const LayerStack& stack,
                                          const PeriodicKernelOptions& o) {
  COATFFT_REQUIRE(g.nx() % 2 == 0 && g.ny() % 2 == 0, "periodic traction kernels: nx = ", g.nx(),
                  " and ny = ", g.ny(), " must be even");
  COATFFT_REQUIRE(o.tolerance > 0 && o.tolerance <= 1e-6,
                  "periodic traction kernels: tolerance must be in (0, 1e-6]");
  COATFFT_REQUIRE(o.threads >= 1 && o.threads <= max_threads,
                  "periodic traction kernels: threads must be in [1, ", max_threads, "]");
  const TractionResponse response = bonded_response(stack);
  const double alpha = detail::ewald_alpha(g);
  const EwaldLattice lattice = make_lattice(g, response, alpha, o);
  const Field zp = periodic_influence_kernel(g, *make_frf(stack), o);
  const Field s = periodic_influence_kernel(g, *in_plane_frf(stack), o);
  std::array<Field, 4> a = lattice_part(g, response, lattice, alpha, o.threads);
  add_short_range(g, response.at_infinity(), alpha, o.threads, a);
  // k = 0 is left out: the short-range parts' integrals over the plane go with the mean.
  for (Field& f : a) f -= f.mean();
  return {zp, s + a[0], s - a[0], std::move(a[1]), std::move(a[2]), std::move(a[3])};
}

double periodic_traction_kernel_evaluations(const Grid& grid, const LayerStack& stack,
                                            const PeriodicKernelOptions& options) {
  return remainder_evaluations(grid,
                               remainder_cut(grid, bonded_response(stack), options.tolerance));
}

}  // namespace coatfft
