#include "model/grid_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>

#include "convolution/operators/make_operator.hpp"
#include "core/detail/fft_size.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft {
namespace {

// The fewest cells per load radius searched: below it the estimator's accuracy is not measured
// (docs/theory.md 4.7), and a centre-sampled load would be a handful of values.
constexpr double min_cells_per_radius = 4.0;
// A window reaches this many load radii from the centre: the domain [-1.5a, 1.5a]^2 on which the
// estimator was calibrated; the largest errors lie at the load's edge, r = a.
constexpr double window_reach = 1.5;
// Refuse without trying max_cells when the fitted model needs more than this many times as many:
// neighbouring sizes can differ by a factor 2 in error (centre sampling), so a model that misses
// by less may still find a grid within the limit.
constexpr double refuse_margin = 2.0;
constexpr int max_trials = 24;

std::ptrdiff_t previous_fast_size(std::ptrdiff_t n) {
  std::ptrdiff_t m = n - 1;
  while (m > 1 && detail::fast_fft_size(m) != m) --m;
  return m;
}

std::ptrdiff_t next_fast_size(std::ptrdiff_t n) {
  return detail::fast_fft_size(n + 1);
}

// Cells of an axis of n cells of size d that cover |x| <= reach, keeping the grid's own cells:
// n - m is a multiple of 4, so the window drops an even number of cells from each end and its
// 2 x 2 blocks (discretization_error.cpp) are those of the whole grid.
std::ptrdiff_t window_cells(std::ptrdiff_t n, double d, double reach) {
  const auto m = static_cast<std::ptrdiff_t>(std::ceil(2.0 * reach / d));
  if (m >= n) return n;
  return n - 4 * ((n - m) / 4);
}

// A cell count along the longer axis and its estimated load error.
struct RefinementPoint {
  std::ptrdiff_t n = 0;  // 0: none
  double estimate = 0.0;
};

class Search {
 public:
  Search(double lx, double ly, const AnalyticLoad& load, double target,
         const GridRefinementOptions& options)
      : lx_(lx), ly_(ly), load_(load), target_(target), options_(options) {}

  // The grid with n cells along the longer axis (x on a tie) and cells no longer along the
  // shorter axis: the fewest fast-size cells there that keep dy <= dx (or dx <= dy).
  Grid grid(std::ptrdiff_t n) const {
    const bool x_long = lx_ >= ly_;
    const double ratio = (x_long ? ly_ / lx_ : lx_ / ly_) * static_cast<double>(n);
    const auto n_short = detail::fast_fft_size(
        std::max<std::ptrdiff_t>(1, static_cast<std::ptrdiff_t>(std::ceil(ratio * (1.0 - 1e-12)))));
    return x_long ? Grid(n, n_short, lx_, ly_) : Grid(n_short, n, lx_, ly_);
  }

  // Cells along the longer axis for `per_radius` cells per load radius (a fast size).
  std::ptrdiff_t cells_for(double per_radius) const {
    const double n = std::ceil(std::max(lx_, ly_) / load_.radius * per_radius);
    return n > 1e15 ? std::numeric_limits<std::ptrdiff_t>::max()
                    : detail::fast_fft_size(static_cast<std::ptrdiff_t>(n));
  }

  // Estimates grid(n) and updates the bracket: the smallest passing size, the largest failing
  // size below it.
  void try_size(std::ptrdiff_t n) {
    const double e = estimate(n);
    if (e <= target_) {
      if (pass_.n == 0 || n < pass_.n) pass_ = {n, e};
      if (fail_.n >= pass_.n) fail_ = {};
    } else if ((pass_.n == 0 || n < pass_.n) && n > fail_.n) {
      fail_ = {n, e};
    }
  }

  // The convergence order from two estimates, clamped to [0.5, 3] (measured 1 to 1.6); only
  // sizes a factor 2 apart are used: between neighbouring sizes the error is too noisy (10 to
  // 50 %, where the load's edge falls in the cells) to give an order.
  void fit_order(const RefinementPoint& coarse, const RefinementPoint& fine) {
    const double order = std::log(coarse.estimate / fine.estimate) /
                         std::log(static_cast<double>(fine.n) / static_cast<double>(coarse.n));
    order_ = std::isfinite(order) ? std::clamp(order, 0.5, 3.0) : 1.0;
  }

  // Cells along the longer axis the power law predicts for the target. Between a failing and a
  // passing size, it interpolates log(estimate) in log(n), kept within the middle 60 % of the
  // bracket so that a noisy pair still shrinks it.
  double predicted_cells() const {
    const auto log_n = [](const RefinementPoint& p) { return std::log(static_cast<double>(p.n)); };
    if (pass_.n > 0 && fail_.n > 0) {
      const double fall = std::log(fail_.estimate / pass_.estimate);
      const double t = fall > 0 ? std::log(fail_.estimate / target_) / fall : 0.5;
      return std::exp(log_n(fail_) + std::clamp(t, 0.2, 0.8) * (log_n(pass_) - log_n(fail_)));
    }
    const RefinementPoint& anchor = pass_.n > 0 ? pass_ : fail_;
    return static_cast<double>(anchor.n) * std::pow(anchor.estimate / target_, 1.0 / order_);
  }

  const RefinementPoint& pass() const { return pass_; }
  const RefinementPoint& fail() const { return fail_; }
  std::vector<GridTrial> tried;

 private:
  // The estimated relative load error on grid(n), on the homogeneous stand-in, recorded.
  double estimate(std::ptrdiff_t n) {
    const Grid full = grid(n);
    const double dx = full.dx(), dy = full.dy(), reach = window_reach * load_.radius;
    const auto mx = window_cells(full.nx(), dx, reach), my = window_cells(full.ny(), dy, reach);
    const Grid window(mx, my, static_cast<double>(mx) * dx, static_cast<double>(my) * dy);
    // Any modulus: Love's coefficients and the displacement both scale with 1/E*, so the
    // relative error of a homogeneous half-space does not depend on it.
    BuiltOperator built = make_operator(window, LayerStack(Material(210e9, 0.3)));
    const Field p = sample_load(window, load_, load_.sampling);
    const double u_max = built.op->apply(p).abs().maxCoeff();
    const double e =
        u_max > 0
            ? options_.body_factor *
                  estimate_load_discretization_error(*built.op, load_, p, u_max).relative_error
            : std::numeric_limits<double>::infinity();
    tried.push_back({full.nx(), full.ny(), e});
    return e;
  }

  double lx_, ly_;
  AnalyticLoad load_;
  double target_;
  GridRefinementOptions options_;
  RefinementPoint pass_, fail_;
  double order_ = 1.0;
};

void check_arguments(double lx, double ly, const AnalyticLoad& load, double tolerance,
                     double operator_share, const GridRefinementOptions& options) {
  check_analytic_load(load);
  COATFFT_REQUIRE(std::isfinite(lx) && lx > 0 && std::isfinite(ly) && ly > 0,
                  "choose_grid_for_tolerance: lx = ", lx, " m, ly = ", ly,
                  " m, but both must be finite and > 0");
  COATFFT_REQUIRE(
      load.radius <= 0.5 * std::min(lx, ly), "choose_grid_for_tolerance: a = ", load.radius,
      " m, but the load radius must be <= min(lx, ly)/2 = ", 0.5 * std::min(lx, ly), " m");
  COATFFT_REQUIRE(tolerance > 0 && tolerance < 1,
                  "choose_grid_for_tolerance: tolerance = ", tolerance,
                  ", but it must be in (0, 1)");
  COATFFT_REQUIRE(operator_share >= 0 && operator_share < 1,
                  "choose_grid_for_tolerance: operator share = ", operator_share,
                  ", but it must be in [0, 1)");
  COATFFT_REQUIRE(options.max_cells >= 1 && options.max_cells <= 65536,
                  "choose_grid_for_tolerance: max_cells = ", options.max_cells,
                  ", but it must be in 1..65536");
  COATFFT_REQUIRE(std::isfinite(options.body_factor) && options.body_factor > 0,
                  "choose_grid_for_tolerance: body_factor = ", options.body_factor,
                  ", but it must be finite and > 0");
}

[[noreturn]] void refuse(double tolerance, double operator_share, double target,
                         const Search& search, double needed, std::ptrdiff_t max_cells) {
  const GridTrial& best = *std::min_element(
      search.tried.begin(), search.tried.end(),
      [](const GridTrial& a, const GridTrial& b) { return a.estimate < b.estimate; });
  std::ostringstream best_estimate;
  best_estimate << std::setprecision(3) << best.estimate;
  throw InvalidArgument(detail::concat(
      "choose_grid_for_tolerance: tolerance = ", tolerance, " is out of reach: the load's share ",
      target, " (operator share ", operator_share, ") needs about ",
      static_cast<double>(std::llround(needed)), " cells along the longer axis, above the limit ",
      max_cells, " (estimated load error ", best_estimate.str(), " on ", best.nx, " x ", best.ny,
      " cells)"));
}

}  // namespace

GridChoice choose_grid_for_tolerance(double lx, double ly, const AnalyticLoad& load,
                                     double tolerance, double operator_share,
                                     const GridRefinementOptions& options) {
  check_arguments(lx, ly, load, tolerance, operator_share, options);
  const double target = (1.0 - operator_share) * tolerance;
  Search search(lx, ly, load, target, options);
  // The largest fast size within the limit: every size tried is a fast size.
  const std::ptrdiff_t max_cells = detail::fast_fft_size(options.max_cells) == options.max_cells
                                       ? options.max_cells
                                       : previous_fast_size(options.max_cells);
  const std::ptrdiff_t n_min = search.cells_for(min_cells_per_radius);
  COATFFT_REQUIRE(n_min <= max_cells, "choose_grid_for_tolerance: tolerance = ", tolerance,
                  " is out of reach: ", min_cells_per_radius,
                  " cells per load radius a = ", load.radius, " m need ", n_min,
                  " cells along the longer axis, above the limit ", max_cells);
  const std::ptrdiff_t n8 = std::clamp(search.cells_for(8.0), n_min, max_cells);
  const std::ptrdiff_t n16 = std::clamp(search.cells_for(16.0), n_min, max_cells);
  search.try_size(n8);
  if (n16 != n8) {
    search.try_size(n16);
    search.fit_order({n8, search.tried[0].estimate}, {n16, search.tried[1].estimate});
  }
  for (int trial = 0; trial < max_trials; ++trial) {
    const RefinementPoint pass = search.pass(), fail = search.fail();
    const std::ptrdiff_t lower = fail.n > 0 ? next_fast_size(fail.n) : n_min;
    const std::ptrdiff_t upper = pass.n > 0 ? previous_fast_size(pass.n) : max_cells;
    if (pass.n > 0 && (pass.n == n_min || lower > upper)) break;
    const double needed = search.predicted_cells();
    if (pass.n == 0 &&
        (fail.n == max_cells || needed > refuse_margin * static_cast<double>(max_cells)))
      refuse(tolerance, operator_share, target, search, needed, max_cells);
    const double wanted =
        std::clamp(needed, static_cast<double>(lower), static_cast<double>(upper));
    search.try_size(std::clamp(
        detail::fast_fft_size(static_cast<std::ptrdiff_t>(std::ceil(wanted))), lower, upper));
  }
  const RefinementPoint pass = search.pass();
  COATFFT_REQUIRE(pass.n > 0, "choose_grid_for_tolerance: tolerance = ", tolerance,
                  ": no grid found after ", max_trials, " trials");
  return GridChoice{search.grid(pass.n), pass.estimate, target, search.tried};
}

double load_error_body_factor(const Frf& frf, const AnalyticLoad& load) {
  check_analytic_load(load);
  const double a = load.radius;
  double c = std::max(frf.c0(), frf.c_inf());
  for (int i = 0; i <= 7 * 16; ++i) {  // k a from 1e-3 to 1e4, 16 per decade
    const double k = std::pow(10.0, -3.0 + i / 16.0) / a;
    c = std::max(c, k * frf(k));
  }
  const bool hertz = load.kind == AnalyticLoad::Kind::hertz;
  // Centre displacements per unit amplitude: docs/theory.md (1.6) and (1.9) with E* = 2/c.
  const double u_half_space = hertz ? std::numbers::pi * a * c / 4.0 : a * c;
  const double u_body = hankel_displacement(
      frf, hertz ? AxisymmetricLoad::hertz : AxisymmetricLoad::uniform_disk, 1.0, a, 0.0, 1e-8);
  return u_half_space / u_body;
}

}  // namespace coatfft
