#include "convolution/kernels/split_frf_kernel.hpp"

#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "convolution/kernels/split_kernel/detail/split_plan.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

// The split kernel (docs/theory.md 4.5), assembled from its plan and its three parts
// (convolution/kernels/split_kernel/): the singular terms, the long range and the short range of
// the remainder.
namespace coatfft {
namespace detail {

namespace {

// F(X, Y) of split_rectangle_integral; odd in X and in Y, F(0, Y) = F(X, 0) = 0.
double corner_beta(double X, double Y, double beta) {
  if (X == 0.0 || Y == 0.0) return 0.0;
  const double X2 = X * X;
  const double Y2 = Y * Y;
  const double b2 = beta * beta;
  return X * std::asinh(Y / std::sqrt(X2 + b2)) + Y * std::asinh(X / std::sqrt(Y2 + b2)) -
         beta * std::atan(X * Y / (beta * std::sqrt(X2 + Y2 + b2)));
}

}  // namespace

double split_rectangle_integral(double x, double y, double dx, double dy, double beta) {
  COATFFT_REQUIRE(std::isfinite(beta) && beta > 0, "split_rectangle_integral: beta = ", beta,
                  " m, but beta must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0,
                  "split_rectangle_integral: cell (", dx, ", ", dy, ") m must be finite and > 0");
  const double a = 0.5 * dx;
  const double b = 0.5 * dy;
  return corner_beta(x + a, y + b, beta) - corner_beta(x + a, y - b, beta) -
         corner_beta(x - a, y + b, beta) + corner_beta(x - a, y - b, beta);
}

}  // namespace detail

namespace detail::split {
namespace {

// Work counts of the plan (split_frf_kernel_work): the fold visits the lattice entries inside
// |k| < k_r (spacing pi/(h d) along an axis), each summing its (2 p_max + 1) aliases per axis
// (half of them on a symmetric lattice); the long part evaluates its Hankel table and a rule of
// nodes^2 points per cell (9 with the stencil, ~8 panels per side when graded).
double fold_terms(const SplitPlan& p) {
  if (!p.short_range || (p.lattice_x.h == 0 && p.lattice_y.h == 0)) return 0.0;
  const auto axis_entries = [&](const LatticeAxis& a, double d) {
    if (a.h == 0) return 1.0;
    return std::min(static_cast<double>(a.h + 1), p.k_r * static_cast<double>(a.h) * d / pi + 1);
  };
  const auto aliases = [](const LatticeAxis& a) { return a.h == 0 ? 1.0 : 2.0 * a.p_max + 1.0; };
  const double entries = axis_entries(p.lattice_x, p.dx) * axis_entries(p.lattice_y, p.dy);
  const bool symmetric = p.dx == p.dy && p.lattice_x.h == p.lattice_y.h;
  return (symmetric ? 0.5 : 1.0) * (pi / 4.0) * entries * aliases(p.lattice_x) *
         aliases(p.lattice_y);
}

double cell_nodes(const SplitPlan& p) {
  const double cells = static_cast<double>(p.nx) * static_cast<double>(p.ny);
  if (p.stencil) return 9.0 * cells;
  const auto per_axis = [](const AxisQuadrature& q) { return q.graded ? 16.0 : q.nodes * q.sub; };
  return cells * per_axis(p.quad_x) * per_axis(p.quad_y);
}

}  // namespace
}  // namespace detail::split

SplitKernelWork split_frf_kernel_work(const Grid& grid, const Frf& frf,
                                      const SplitKernelOptions& options) {
  const detail::split::SplitPlan p = detail::split::make_split_plan(grid, frf, options);
  SplitKernelWork work;
  work.lattice_entries = p.lattice_entries;
  work.lattice_fits = p.lattice_entries <= detail::split::max_lattice_entries;
  work.remainder_zero = p.remainder_zero;
  if (p.remainder_zero) return work;
  work.fold_terms = detail::split::fold_terms(p);
  if (p.long_range) {
    const double r_table = std::min(p.r_max, p.r_uniform);
    const double nodes =
        static_cast<double>(detail::split::hankel_panel_nodes * (p.panel_edges.size() - 1));
    work.hankel_evaluations = nodes * r_table / p.dr;
    work.cell_nodes = detail::split::cell_nodes(p);
  }
  return work;
}

// The method of split_frf_kernel.hpp, part by part. The kernel is even in x and y: only its
// quarter di, dj >= 0 is computed (DcfftOperator transforms it directly, and the (2nx, 2ny)
// wrap-around array, 32 MiB at 1024^2, is never formed).
InfluenceKernel split_frf_kernel(const Grid& grid, const Frf& frf,
                                 const SplitKernelOptions& options, SplitKernelReport* report) {
  const auto start = std::chrono::steady_clock::now();
  const detail::split::SplitPlan plan = detail::split::make_split_plan(grid, frf, options);
  detail::split::require_lattice(plan);
  SplitKernelReport rep;
  detail::split::report_plan(plan, rep);
  Field quarter(plan.nx + 1, plan.ny + 1);
  std::vector<double> spare;  // scratch shared by the two parts of R
  const detail::split::QuarterRows rows{quarter.data(), plan.nx, 0, plan.ny + 1};
  detail::split::assign_singular_terms(plan, rows);                              // (a) + (b)
  if (plan.long_range) detail::split::add_long_range(plan, rows, spare, rep);    // (c) R w
  if (plan.short_range) detail::split::add_short_range(plan, rows, spare, rep);  // (c) R (1 - w)
  // The offsets nx and ny are never used by the convolution: 0 by convention.
  quarter.row(plan.nx).setZero();
  quarter.col(plan.ny).setZero();
  rep.seconds = detail::seconds_since(start);
  if (report != nullptr) *report = rep;
  return InfluenceKernel(grid, InfluenceKernel::Form::coefficients, std::move(quarter),
                         Method::frf_split);
}

}  // namespace coatfft
