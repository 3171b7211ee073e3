#include "convolution/kernels/split_kernel/detail/split_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/threads.hpp"

namespace coatfft::detail::split {
namespace {

void check_options(const SplitKernelOptions& options) {
  COATFFT_REQUIRE(std::isfinite(options.beta) && options.beta >= 0,
                  "split_frf_kernel: beta = ", options.beta,
                  " m, but beta must be finite and >= 0 (0 = automatic)");
  COATFFT_REQUIRE(std::isfinite(options.sigma) && options.sigma >= 0,
                  "split_frf_kernel: sigma = ", options.sigma,
                  " m, but sigma must be finite and >= 0 (0 = automatic)");
  COATFFT_REQUIRE(options.tolerance > 0 && options.tolerance <= 1e-3,
                  "split_frf_kernel: tolerance = ", options.tolerance,
                  ", but it must be in (0, 1e-3]");
  COATFFT_REQUIRE(options.threads >= 1 && options.threads <= max_threads,
                  "split_frf_kernel: threads = ", options.threads, ", but it must be in [1, ",
                  max_threads, "]");
  COATFFT_REQUIRE(options.max_alias_order >= 0 && options.max_alias_order <= 4096,
                  "split_frf_kernel: max_alias_order = ", options.max_alias_order,
                  ", but it must be in [0, 4096]");
}

// The alias order |p| that folds every |k| < k_r along a cell side d.
double alias_need(const SplitPlan& p, double d) {
  return std::ceil(p.k_r * d / (2.0 * pi) + 0.5);
}

// A cell side >= wide_cells sigma is a wide axis (add_short_range): the short-range kernel is
// left out beyond half of it, 64 sigma. It decays like r^-9 in R's far field, but where R has a
// length scale b above sigma it is (sigma^6/6) (-lap)^3 of R's kernel and reaches a few b, and a
// wide cell collects it over its whole length: cut at 32 sigma (cells of 0.5 um x 2 mm,
// b = 6 sigma) it cost 7e-10 of K(0, 0), at 64 sigma 1e-11.
constexpr double wide_cells = 128.0;

// The default window length: min(lx, ly)/32, so that the Hankel table costs the same for every
// N, but at least 1.5 times the shorter cell side, so that the long part needs no subdivision of
// the cells across. Not the longer side: the lattice half-size 32 sigma/d along the short side
// would grow with the cell aspect ratio (48 dy/dx with 1.5 max(dx, dy)); the long side is
// subdivided instead (axis_quadrature, graded_rule). A side >= 8 times the other that needs more
// than 4 aliases (a layer thinner than ~1/4 of that side) gets sigma = side/128, which makes the
// axis wide: it then needs no alias at all, where the fold would cost (2P + 1) terms per lattice
// entry or be truncated at max_alias_order (1 x 4096 cells of 2 mm x 0.5 um, TiN 20 um:
// P = 469), and the long part's rules, graded in r, cost a few points per far cell. The short
// side stays within 16 sigma.
double automatic_sigma(const SplitPlan& p) {
  double sigma = std::max(std::min(p.lx, p.ly) / 32.0, 1.5 * p.d_min);
  const double many_aliases = std::min(4, p.max_alias_order);
  for (const double d : {p.dx, p.dy})
    if (alias_need(p, d) > many_aliases && d / wide_cells >= p.d_min / 16.0)
      sigma = std::min(sigma, d / wide_cells);
  return sigma;
}

// The window length sigma and the cut-offs of the two parts of R.
void choose_window(SplitPlan& p, const SplitKernelOptions& options) {
  p.sigma = options.sigma > 0 ? options.sigma : automatic_sigma(p);
  if (options.route == SplitRoute::periodic) p.sigma = 0.0;
  if (options.route == SplitRoute::hankel) p.sigma = std::numeric_limits<double>::infinity();
  // w < tol beyond k_c: exp(-s) s^2/2 < tol at s = log_tol + 2 log(log_tol) (two Newton-free
  // fixed-point steps suffice for the tolerances allowed).
  p.s_c = p.log_tol;
  for (int it = 0; it < 4; ++it) p.s_c = p.log_tol + 2.0 * std::log(p.s_c) - std::log(2.0);
  p.k_c = std::isinf(p.sigma) ? p.k_r : std::min(p.k_r, std::sqrt(p.s_c) / p.sigma);
  p.long_range = p.sigma > 0.0 && p.k_c > 0.0;
  p.short_range = !std::isinf(p.sigma) && p.k_r > 0.0;
  p.wide_x = p.short_range && p.sigma > 0.0 && p.dx >= wide_cells * p.sigma;
  p.wide_y = p.short_range && p.sigma > 0.0 && p.dy >= wide_cells * p.sigma;
}

// The reach of the short-range kernel that the lattice keeps free of images along one axis:
// 32 sigma, or 64 sigma when the other axis is wide, for the reasons of wide_cells (a wide cell
// weighs the images by its length; cells of 83 um x 8.3 mm, b = 8 sigma: 1.3e-9 of K(0, 0) at
// 32 sigma, 1e-11 at 64 sigma; the 1-D lattice of a wide cell costs little either way).
double lattice_reach(const SplitPlan& p, bool other_wide) {
  return (other_wide ? 64.0 : 32.0) * p.sigma;
}

// One axis of the lattice: the half period keeps the images of the short-range kernel beyond
// lattice_reach (and >= the domain, so that every offset is an entry); the alias order folds
// every |k| < k_r, capped at max_alias_order.
LatticeAxis lattice_axis(const SplitPlan& p, std::ptrdiff_t n, double d, bool wide,
                         bool other_wide) {
  if (wide) return {};
  LatticeAxis a;
  a.h = static_cast<std::ptrdiff_t>(
      std::max(static_cast<double>(n), std::ceil(lattice_reach(p, other_wide) / d)));
  const double need = alias_need(p, d);
  a.capped = need > p.max_alias_order;
  a.p_max = static_cast<int>(std::min<double>(need, p.max_alias_order));
  return a;
}

// The lattice of the short-range part. Its size is checked by require_lattice before any
// allocation; a plan whose lattice would not fit gets no axes, so that the work estimate of a grid
// the split kernel cannot take stays cheap.
void choose_lattice(SplitPlan& p) {
  const double hx =
      std::max(static_cast<double>(p.nx), std::ceil(lattice_reach(p, p.wide_y) / p.dx));
  const double hy =
      std::max(static_cast<double>(p.ny), std::ceil(lattice_reach(p, p.wide_x) / p.dy));
  p.lattice_entries = (p.wide_x ? 1.0 : hx + 1.0) * (p.wide_y ? 1.0 : hy + 1.0);
  if (p.lattice_entries > p.lattice_limit) return;
  p.lattice_x = lattice_axis(p, p.nx, p.dx, p.wide_x, p.wide_y);
  p.lattice_y = lattice_axis(p, p.ny, p.dy, p.wide_y, p.wide_x);
}

}  // namespace

// A lattice that would not fit is refused before it is allocated: a sigma given by the caller
// that is huge against a cell, or a grid of more than ~11585^2 cells (the lattice covers every
// offset of the domain); the automatic sigma keeps the half sizes <= max(2n, 96).
void require_lattice(const SplitPlan& p) {
  COATFFT_REQUIRE(p.lattice_entries <= p.lattice_limit, "split_frf_kernel: sigma = ", p.sigma,
                  " m against cells of ", p.dx, " x ", p.dy, " m on ", p.nx, " x ", p.ny,
                  " cells needs a short-range lattice of ", p.lattice_entries,
                  " entries (more than ", p.lattice_limit,
                  "); use fewer cells, leave sigma automatic (0), or use frf-spectral");
}

// Panels of the Hankel transform: geometric (halving) from the first uniform panel down to R's
// smallest scale, then uniform of width <= 2 pi / r_max (one J0 period at r_max) up to k_c.
std::vector<double> hankel_panel_edges(double k_c, double r_max, double k_lo) {
  const double dk_u = std::min(4.0 * pi / r_max, k_c);
  std::vector<double> edges = {0.0};
  std::vector<double> geo;
  for (double e = dk_u * 0.5; e > k_lo; e *= 0.5) geo.push_back(e);
  std::reverse(geo.begin(), geo.end());
  edges.insert(edges.end(), geo.begin(), geo.end());
  const auto nu = static_cast<std::ptrdiff_t>(std::ceil(k_c / dk_u));
  for (std::ptrdiff_t i = 1; i <= nu; ++i)
    edges.push_back(k_c * static_cast<double>(i) / static_cast<double>(nu));
  return edges;
}

// Gauss-Legendre points per panel for a panel `ratio` times shorter than the length on which the
// kernel is smooth. The n-point error on a panel of width w is about c_n (w/(sqrt(2) ell))^(2n)
// with c_2 = 2e-4, c_3 = 7e-7, c_4 = 7e-9, c_5 = 3e-11, c_6 = 2e-12: ~1e-13 relative.
int nodes_for_ratio(double ratio) {
  return ratio >= 24.0 ? 2 : ratio >= 12.0 ? 3 : ratio >= 4.0 ? 4 : ratio >= 2.5 ? 5 : 6;
}

namespace {

// Beyond this many uniform panels per cell side the panels are graded (graded_rule).
constexpr double max_uniform_panels = 8.0;

// Panels of <= ell/1.5 per cell side d.
AxisQuadrature axis_quadrature(double ell, double d) {
  AxisQuadrature q;
  const double sub = std::ceil(d / (ell / 1.5));
  q.graded = sub > max_uniform_panels;
  q.sub = static_cast<int>(std::clamp(sub, 1.0, max_uniform_panels));
  q.nodes = nodes_for_ratio(ell * q.sub / d);
  return q;
}

// The Hankel table and the rule over each cell of the long-range part.
void choose_long_range_rules(SplitPlan& p) {
  p.r_max = std::hypot(p.lx, p.ly) + 4.0 * p.d_max;  // the stencil reads 4 cells beyond
  // The uniform table (step 0.5/k_c) stops at 128 sigma_e, sigma_e = sqrt(s_c)/k_c the window
  // length of the band limit; the tail beyond is tabulated in log r (tail_table). Domains up
  // to an aspect ratio of ~4 (r_max ~ 45 sigma when square) never reach it.
  const double sigma_e = std::sqrt(p.s_c) / p.k_c;
  p.r_uniform =
      p.r_max <= 128.0 * sigma_e ? std::numeric_limits<double>::infinity() : 128.0 * sigma_e;
  const double r_table = std::min(p.r_max, p.r_uniform);
  p.panel_edges = hankel_panel_edges(p.k_c, std::min(std::hypot(p.lx, p.ly), r_table), p.k_lo);
  // g is band-limited to k_c: 6-point interpolation with k_c dr = 0.3 is accurate to ~1e-9 of
  // g's scale (checked against a table with half the step in the tests).
  p.dr = 0.5 / p.k_c;
  const double nodes = static_cast<double>(hankel_panel_nodes * (p.panel_edges.size() - 1));
  const double cost = nodes * (r_table / p.dr);
  // Bounded through r_uniform (a few million at most); kept as a guard before the allocation.
  COATFFT_REQUIRE(cost < 4e9, "split_frf_kernel: the Hankel table would need ", cost,
                  " Bessel evaluations; use SplitRoute::automatic");
  // Rule per cell and axis: the kernel is smooth on the scale ell = sqrt(log_tol)/k_c (about
  // sigma; its spectrum is cut like a Gaussian of width sqrt(2) sigma); panels <= ell/1.5.
  p.ell = std::sqrt(p.log_tol) / p.k_c;
  p.quad_x = axis_quadrature(p.ell, p.dx);
  p.quad_y = axis_quadrature(p.ell, p.dy);
  // Where the long kernel is smooth on >= 8 cells, one point value per cell and the 9-point
  // cell-average stencil replace the rule (add_long_range_by_stencil).
  p.stencil = p.ell >= 8.0 * p.d_max;
}

}  // namespace

void report_plan(const SplitPlan& p, SplitKernelReport& rep) {
  rep.c0 = p.c0;
  rep.c_inf = p.c_inf;
  rep.beta = p.beta;
  rep.remainder_zero = p.remainder_zero;
  if (p.remainder_zero) return;
  rep.sigma = p.sigma;
  rep.alias_order = std::max(p.lattice_x.p_max, p.lattice_y.p_max);
  rep.alias_capped = p.lattice_x.capped || p.lattice_y.capped;
  rep.wide_x = p.wide_x;
  rep.wide_y = p.wide_y;
  if (!p.long_range) return;
  const bool graded = p.quad_x.graded || p.quad_y.graded;
  rep.cell_rule = p.stencil ? 1
                  : graded  ? 0
                           : std::max(p.quad_x.nodes * p.quad_x.sub, p.quad_y.nodes * p.quad_y.sub);
}

SplitPlan make_split_plan(const Grid& grid, const Frf& frf, const SplitKernelOptions& options,
                          int lattice_ranks) {
  check_options(options);
  SplitPlan p;
  p.lattice_limit = max_lattice_entries * lattice_ranks;
  p.nx = grid.nx();
  p.ny = grid.ny();
  p.dx = grid.dx();
  p.dy = grid.dy();
  p.lx = grid.lx();
  p.ly = grid.ly();
  p.d_min = std::min(p.dx, p.dy);
  p.d_max = std::max(p.dx, p.dy);
  p.near_r = 32.0 * p.d_max;
  p.tolerance = options.tolerance;
  p.log_tol = std::log(1.0 / options.tolerance);
  p.max_alias_order = options.max_alias_order;
  p.threads = options.threads;
  p.c0 = frf.c0();
  p.c_inf = frf.c_inf();
  COATFFT_REQUIRE(std::isfinite(p.c0) && p.c0 > 0, "split_frf_kernel: c0 = ", p.c0,
                  " 1/Pa of FRF '", frf.name(), "', but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(p.c_inf) && p.c_inf > 0, "split_frf_kernel: c_inf = ", p.c_inf,
                  " 1/Pa of FRF '", frf.name(), "', but it must be finite and > 0");
  p.c_max = std::max(p.c0, p.c_inf);
  p.A = p.c0 - p.c_inf;
  const Remainder probe(frf, p.c_inf, p.A, 1.0);
  const Scan scan = scan_frf(probe, p.A, p.c_max, std::min(p.dx, p.dy), std::max(p.lx, p.ly));
  p.beta = p.A == 0.0 ? 0.0 : (options.beta > 0 ? options.beta : scan.beta);
  p.remainder_zero = scan.remainder_zero;
  p.k_lo = scan.k_lo;
  if (p.remainder_zero) return p;
  p.remainder = Remainder(frf, p.c_inf, p.A, p.beta);
  p.remainder.tabulate(scan.k_lo, std::max(scan.k_hi, p.A != 0.0 ? 50.0 / p.beta : 0.0), 400);
  p.k_r = remainder_cutoff(p.remainder, p.A, p.beta, p.tolerance * p.c_max);
  choose_window(p, options);
  if (p.short_range) choose_lattice(p);
  if (p.long_range) choose_long_range_rules(p);
  return p;
}

}  // namespace coatfft::detail::split
