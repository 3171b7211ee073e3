#include "convolution/kernels/traction_kernels.hpp"

#include <array>
#include <chrono>
#include <cmath>

#include "convolution/kernels/angular_influence.hpp"
#include "convolution/kernels/cerruti_influence.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "frf/frf.hpp"
#include "frf/traction_response.hpp"

namespace coatfft {

namespace {

// The homogeneous half-space: Love's u_z under p, Cerruti's (xx, yx, zx) under q_x and, with the
// axes swapped, under q_y (docs/theory.md 1.3b), all in closed form.
TractionKernels half_space(const Grid& g, const Material& m, int threads) {
  const std::ptrdiff_t nx = g.nx(), ny = g.ny();
  const double dx = g.dx(), dy = g.dy();
  TractionKernels c{Field(nx, ny), Field(nx, ny), Field(nx, ny),
                    Field(nx, ny), Field(nx, ny), Field(nx, ny)};
  detail::parallel_for(0, ny, threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      const double x = i * dx, y = j * dy;
      c.zp(i, j) = love_influence(x, y, dx, dy) / m.plane_strain_modulus();
      const CerrutiCoefficients q = cerruti_influence(x, y, dx, dy, m);
      c.xx(i, j) = q.xx;
      c.yx(i, j) = q.yx;
      c.zx(i, j) = q.zx;
      const CerrutiCoefficients swapped = cerruti_influence(y, x, dy, dx, m);
      c.yy(i, j) = swapped.xx;
      c.zy(i, j) = swapped.zx;
    }
  });
  return c;
}

// The split of D and C (docs/theory.md (2.9.4)-(2.9.5)): f_inf/k + (f_0 - f_inf) exp(-beta k)/k +
// r_0 exp(-beta k) + R(k). rd0, rc0 are r_0 of D and C: the limit of the bounded remainder as
// k -> 0, which the lattice, taking 0 at k = 0, must not see (a cos(n theta)/r^2 tail whose
// periodic images would grow across the domain).
struct Split {
  TractionFrfs f0, fi;
  double beta;
  double rd0 = 0.0, rc0 = 0.0;
  /// R_D and R_C at k > 0 (less r_0 exp(-beta k) when `flat` is set).
  std::array<double, 2> remainder(const TractionFrfs& f, double k, bool flat = true) const {
    const double e = std::exp(-beta * k);
    return {f.d - (fi.d + (f0.d - fi.d) * e) / k - (flat ? rd0 * e : 0.0),
            f.c - (fi.c + (f0.c - fi.c) * e) / k - (flat ? rc0 * e : 0.0)};
  }
};

// r_0 of D and C: the remainders are analytic in k (functions of exp(-2 k h_i) and k h_i over
// k), so the extrapolation 3 R(k) - 3 R(2k) + R(4k) from k beta = 1e-3 is exact to O((k beta)^3)
// ~ 1e-9 relative; the 1/k terms cancel there to ~1e-13.
Split make_split(const TractionResponse& response, double beta) {
  Split s{response.at_zero(), response.at_infinity(), beta};
  const double k = 1e-3 / beta;
  const auto r = [&](double m) { return s.remainder(response(m * k), m * k, false); };
  const auto r1 = r(1.0), r2 = r(2.0), r4 = r(4.0);
  s.rd0 = 3.0 * r1[0] - 3.0 * r2[0] + r4[0];
  s.rc0 = 3.0 * r1[1] - 3.0 * r2[1] + r4[1];
  return s;
}

// The closed-form terms of the split of D and C. dc is the kernel of D cos 2theta (u_x under q_x
// less that of S).
struct AngularPart {
  Field dc, yx, zx, zy;
};

AngularPart angular_part(const Grid& g, const Split& sp, int threads) {
  const std::ptrdiff_t nx = g.nx(), ny = g.ny();
  const double dx = g.dx(), dy = g.dy(), beta = sp.beta;
  AngularPart a{Field(nx, ny), Field(nx, ny), Field(nx, ny), Field(nx, ny)};
  const double dd = sp.f0.d - sp.fi.d, dc = sp.f0.c - sp.fi.c;
  detail::parallel_for(0, ny, threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      const double x = i * dx, y = j * dy;
      const AngularCoefficients top = angular_influence(x, y, dx, dy, 0.0);
      const AngularCoefficients deep = angular_influence(x, y, dx, dy, beta);
      const AngularCoefficients flat = angular_flat_influence(x, y, dx, dy, beta);
      a.dc(i, j) = sp.fi.d * top.cos2 + dd * deep.cos2 + sp.rd0 * flat.cos2;
      a.yx(i, j) = sp.fi.d * top.sin2 + dd * deep.sin2 + sp.rd0 * flat.sin2;
      a.zx(i, j) = sp.fi.c * top.cos1 + dc * deep.cos1 + sp.rc0 * flat.cos1;
      const double top_y = angular_influence(y, x, dy, dx, 0.0).cos1;
      const double deep_y = angular_influence(y, x, dy, dx, beta).cos1;
      const double flat_y = angular_flat_influence(y, x, dy, dx, beta).cos1;
      a.zy(i, j) = sp.fi.c * top_y + dc * deep_y + sp.rc0 * flat_y;
    }
  });
  return a;
}

// The remainders R'_D, R'_C of the split on the lattices, as the spectra of (dc, yx, zx, zy):
// G = i^(odd_x + odd_y) F with F = R'_D cos 2theta, R'_D sin 2theta, -i R'_C cos theta,
// -i R'_C sin theta.
void add_remainders(const Grid& g, const TractionResponse& response, const Split& sp,
                    const TractionKernelOptions& o, AngularPart& a, LatticeReport& report) {
  LatticeSpectra s;
  s.parity = {{false, false}, {true, true}, {true, false}, {false, true}};
  // |R'| <= (a polynomial in k beta) exp(-k beta) of the half-space terms (docs/theory.md 2.9.4).
  s.k_cut = exponential_cut_off(sp.beta, o.tolerance);
  s.sample = [&](double kx, double ky, double k, std::span<double> out) {
    const auto [rd, rc] = sp.remainder(response(k), k);
    const double c = kx / k, sn = ky / k;
    out[0] = rd * (c * c - sn * sn);
    out[1] = -rd * 2.0 * c * sn;
    out[2] = rc * c;
    out[3] = rc * sn;
  };
  const std::vector<Field> r =
      lattice_coefficients(g, s, o.lattice, "traction kernels of a layered body", &report);
  a.dc += r[0];
  a.yx += r[1];
  a.zx += r[2];
  a.zy += r[3];
}

TractionKernels layered(const Grid& g, const LayerStack& stack, const TractionKernelOptions& o,
                        TractionKernelReport& report) {
  const TractionResponse response(stack);
  COATFFT_REQUIRE(response.bonded(),
                  "traction kernels: tangential tractions need every interface bonded (a coating "
                  "over a frictionless interface has no equilibrium under a net tangential force)");
  COATFFT_REQUIRE(o.tolerance > 0 && o.tolerance <= 1e-3,
                  "traction kernels: tolerance must be in (0, 1e-3]");
  const int threads = o.lattice.threads;
  SplitKernelOptions split = o.split;
  split.threads = threads;
  const auto radial = [&](const Frf& f) {
    return Field(split_frf_kernel(g, f, split).quarter().topLeftCorner(g.nx(), g.ny()));
  };
  const Field zp = radial(*make_frf(stack));
  const Field s = radial(*in_plane_frf(stack));
  report.beta = stack.coatings().front().thickness;
  const Split sp = make_split(response, report.beta);
  AngularPart a = angular_part(g, sp, threads);
  add_remainders(g, response, sp, o, a, report.lattice);
  return {zp, s + a.dc, s - a.dc, std::move(a.yx), std::move(a.zx), std::move(a.zy)};
}

}  // namespace

TractionKernels traction_kernels(const Grid& grid, const LayerStack& stack,
                                 const TractionKernelOptions& options,
                                 TractionKernelReport* report) {
  const auto start = std::chrono::steady_clock::now();
  COATFFT_REQUIRE(options.lattice.threads >= 1 && options.lattice.threads <= max_threads,
                  "traction kernels: threads = ", options.lattice.threads, " must be in 1..",
                  max_threads);
  TractionKernelReport r;
  TractionKernels k = stack.is_homogeneous()
                          ? half_space(grid, stack.substrate(), options.lattice.threads)
                          : layered(grid, stack, options, r);
  r.seconds = detail::seconds_since(start);
  if (report) *report = r;
  return k;
}

double traction_kernel_evaluations(const Grid& grid, const LayerStack& stack,
                                   const TractionKernelOptions& options) {
  if (stack.is_homogeneous()) return 0.0;
  const double beta = stack.coatings().front().thickness;
  return lattice_evaluations(grid, exponential_cut_off(beta, options.tolerance),
                             options.lattice.alpha);
}

}  // namespace coatfft
