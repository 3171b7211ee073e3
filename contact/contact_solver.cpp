#include "contact/contact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "contact/detail/cell_passes.hpp"
#include "contact/detail/fourier_preconditioner.hpp"
#include "contact/detail/load_scaling.hpp"
#include "contact/detail/polonsky_keer_iteration.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace coatfft {

namespace {

// How a solve's iterations ended: the status and the number of iterations done.
struct IterationEnd {
  ContactStatus status = ContactStatus::iteration_limit;
  int iterations = 0;
};

// Iterates until the iteration ends or options.max_iterations are done, checking for interrupts
// before each iteration and reporting each step to options.on_iteration.
IterationEnd iterate_to_end(detail::PolonskyKeerIteration& iteration, const ContactOptions& options,
                            const detail::SolverRanks* ranks) {
  IterationEnd done;
  while (done.iterations < options.max_iterations) {
    // The iterate lives here and is dropped on the way out: the operator and the solver are
    // left as they were, ready for another solve.
    // Distributed, the ranks stop together: one that stopped alone would leave the others
    // waiting in the next sum.
    if (!ranks) {
      check_interrupt();
    } else if (!detail::all_over(ranks, !detail::poll_interrupt())) {
      throw Interrupted();
    }
    ++done.iterations;
    const std::optional<ContactStatus> end = iteration.iterate(options.tolerance);
    const bool stepped = !end || *end == ContactStatus::converged;
    if (stepped && options.on_iteration)
      options.on_iteration(done.iterations, iteration.residual());
    if (end) {
      done.status = *end;
      break;
    }
  }
  return done;
}

}  // namespace

std::vector<double> sweep_order(std::vector<double> values, bool unload) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  if (unload && n > 0)
    for (std::size_t k = n - 1; k-- > 0;)
      if (values[k] < values[n - 1]) values.push_back(values[k]);
  return values;
}

ContactSolver::ContactSolver(SurfaceOperator& op, ContactOptions options)
    : ContactSolver(op, std::move(options), nullptr) {}

ContactSolver::ContactSolver(SurfaceOperator& op, ContactOptions options,
                             std::shared_ptr<const detail::SolverRanks> ranks)
    : op_(op), options_(std::move(options)), ranks_(std::move(ranks)) {
  COATFFT_REQUIRE(std::isfinite(options_.tolerance) && options_.tolerance > 0,
                  "ContactSolver: tolerance = ", options_.tolerance,
                  ", but it must be finite and > 0");
  COATFFT_REQUIRE(options_.threads >= 1, "ContactSolver: threads = ", options_.threads,
                  ", but it must be >= 1");
  COATFFT_REQUIRE(options_.max_iterations >= 1,
                  "ContactSolver: max_iterations = ", options_.max_iterations,
                  ", but it must be >= 1");
  COATFFT_REQUIRE(
      !options_.hardness || (std::isfinite(*options_.hardness) && *options_.hardness > 0),
      "ContactSolver: hardness = ", options_.hardness.value_or(0.0),
      " Pa, but it must be finite and > 0");
  if (options_.preconditioned) {
    // Applied once per iteration: FFTW_MEASURE pays for its planning from 2048^2 cells
    // (docs/contact.md, "Preconditioning").
    constexpr std::ptrdiff_t measured_cells = 2048 * 2048;
    const Planning planning = options_.preconditioner_planning.value_or(
        op_.grid().nb_cells() >= measured_cells ? Planning::measure : Planning::estimate);
    if (ranks_) {
      preconditioner_ = ranks_->preconditioner(op_, options_.threads, planning);
    } else {
      // On a periodic operator of double precision the two share one filter: its plans and its
      // spectrum buffer, a field's memory (docs/scale.md, "Memory per cell").
      const auto* periodic = dynamic_cast<const PeriodicOperator*>(&op_);
      auto fourier =
          periodic && periodic->precision() == Precision::double_precision
              ? std::make_unique<detail::FourierPreconditioner>(periodic->spectral_filter())
              : std::make_unique<detail::FourierPreconditioner>(op_.grid(), options_.threads,
                                                                planning);
      if (op_.periodic() &&
          options_.preconditioner_symbol == PreconditionerSymbol::operator_adapted) {
        fourier->adapt_to_kernel(op_.unit_response());
        pending_applications_ = 1;  // reported by the first solve
      }
      preconditioner_ = std::move(fourier);
    }
  }
}

ContactSolver::~ContactSolver() = default;

void ContactSolver::check_value(ContactControl control, double value) const {
  if (control == ContactControl::load)
    COATFFT_REQUIRE(std::isfinite(value) && value > 0, "ContactSolver: load = ", value,
                    " N, but the total load must be finite and > 0");
  else
    COATFFT_REQUIRE(std::isfinite(value), "ContactSolver: approach = ", value,
                    " m, but it must be finite");
}

ContactResult ContactSolver::solve_load(const Field& height, double load) {
  check_value(ContactControl::load, load);
  return run(height, ContactControl::load, load, std::nullopt);
}

ContactResult ContactSolver::solve_approach(const Field& height, double approach) {
  check_value(ContactControl::approach, approach);
  return run(height, ContactControl::approach, approach, std::nullopt);
}

ContactResult ContactSolver::solve(const Field& height, ContactControl control, double value) {
  return control == ContactControl::load ? solve_load(height, value)
                                         : solve_approach(height, value);
}

ContactResult ContactSolver::solve_from(const Field& height, ContactControl control, double value,
                                        Field start) {
  check_value(control, value);
  COATFFT_REQUIRE(start.rows() == height.rows() && start.cols() == height.cols(),
                  "ContactSolver: the start pressure's shape differs from the heights'");
  return run(height, control, value, std::optional<Field>(std::move(start)));
}

std::vector<ContactResult> ContactSolver::solve_sweep(const Field& height, ContactControl control,
                                                      std::vector<double> values, bool unload) {
  COATFFT_REQUIRE(!values.empty(), "ContactSolver: a sweep needs at least one value");
  for (const double value : values) {  // all before any work
    check_value(control, value);
    check_problem(height, control, value);
  }
  values = sweep_order(std::move(values), unload);
  // Under a hardness the surface keeps the plastic depth of the steps before (a loading
  // history): the heights of each step are the heights plus that depth.
  Field depth;
  Field carried;
  if (options_.hardness) depth = Field::Zero(height.rows(), height.cols());
  std::vector<ContactResult> results;
  for (const double value : values) {
    Field start;
    const std::size_t k = results.size();
    if (options_.on_value) options_.on_value(k, values.size(), value);
    if (k >= 2 && values[k - 1] != values[k - 2]) {
      // The secant through the last two solutions: exact while the contact set holds (p is then
      // linear in the load and in the approach). A repeated value starts from its twin.
      const double t = (value - values[k - 1]) / (values[k - 1] - values[k - 2]);
      start = results[k - 1].pressure + t * (results[k - 1].pressure - results[k - 2].pressure);
    } else if (k >= 1) {
      start = results[k - 1].pressure;
    }
    if (options_.hardness && k > 0) carried = height + depth;
    const Field& h = options_.hardness && k > 0 ? carried : height;
    results.push_back(
        run(h, control, value, k == 0 ? std::nullopt : std::optional<Field>(std::move(start))));
    if (options_.hardness) {
      depth += results.back().plastic_depth;
      results.back().plastic_depth = depth;
    }
  }
  return results;
}

void ContactSolver::check_problem(const Field& h, ContactControl control, double value) const {
  const Grid& grid = op_.grid();
  const detail::SolverRanks* ranks = ranks_.get();
  // Distributed: this rank's rows of the heights (every check is made by all ranks together).
  const std::ptrdiff_t rows = ranks ? ranks->rows() : grid.ny();
  COATFFT_REQUIRE(detail::all_over(ranks, h.rows() == grid.nx() && h.cols() == rows),
                  "ContactSolver: height field of shape (", h.rows(), ", ", h.cols(),
                  "), but the operator's grid is (", grid.nx(), ", ", grid.ny(), ")",
                  ranks ? " (distributed: a rank's rows)" : "");
  COATFFT_REQUIRE(detail::all_over(ranks, h.allFinite()),
                  "ContactSolver: the height field has a non-finite entry");
  if (control == ContactControl::load && options_.hardness) {
    // No pressure within the cap carries more than the hardness times the domain's area.
    const double capacity = *options_.hardness * grid.lx() * grid.ly();
    COATFFT_REQUIRE(value < capacity, "ContactSolver: load = ", value,
                    " N, but under hardness = ", *options_.hardness,
                    " Pa it must stay below the hardness times the domain's area, ", capacity,
                    " N (the whole surface at the hardness)");
  }
  if (control == ContactControl::approach) {
    const double h_min = detail::extrema_over(ranks, h).min;
    COATFFT_REQUIRE(value > h_min, "ContactSolver: approach = ", value,
                    " m, but it must exceed min(height) = ", h_min,
                    " m, or the indenter does not touch the surface");
    // A periodic displacement has zero mean (docs/theory.md 4.8), so the mean gap is
    // mean(h) - delta whatever the pressure: an approach at or beyond mean(h) has no solution
    // (the pressure would grow without bound). Full contact is reached as delta -> mean(h).
    const double h_mean =
        ranks ? detail::sum_over(ranks, h.sum()) / static_cast<double>(grid.nb_cells()) : h.mean();
    // Under a hardness the pressure is bounded: every approach has a solution.
    COATFFT_REQUIRE(options_.hardness || !op_.periodic() || value < h_mean,
                    "ContactSolver: approach = ", value,
                    " m, but on a periodic surface it must stay below mean(height) = ", h_mean,
                    " m (the displacement has zero mean: no contact solves a larger approach)");
  }
}

ContactResult ContactSolver::run(const Field& h, ContactControl control, double value,
                                 std::optional<Field> start) {
  check_problem(h, control, value);
  const auto solve_start = std::chrono::steady_clock::now();
  NestedStart nested;
  if (!start) {
    nested = nested_start(h, control, value);
    start = std::move(nested.pressure);
  }
  int scale_applications = nested.applications;
  const double s = control == ContactControl::load
                       ? detail::load_scale(op_, h, value, scale_applications, ranks_.get())
                       : 1.0;
  Field h_scaled;
  if (s != 1.0) {
    h_scaled = detail::work_field(h);
    h_scaled = h / s;
  }
  COATFFT_REQUIRE(
      s == 1.0 || (detail::all_over(ranks_.get(), h_scaled.allFinite()) && value / s > 0),
      "ContactSolver: load = ", value, " N and heights spanning ",
      detail::extrema_over(ranks_.get(), h).max - detail::extrema_over(ranks_.get(), h).min,
      " m are too far apart for double precision; rescale their units");
  ContactOptions options = options_;  // the hardness in the scaled problem's units
  if (options.hardness) *options.hardness /= s;
  detail::PolonskyKeerIteration iteration(op_, preconditioner_.get(), ranks_.get(),
                                          s == 1.0 ? h : h_scaled, control, value / s, options,
                                          std::move(start));
  const double start_seconds = detail::seconds_since(solve_start);
  iteration.timings() = ContactTimings{};  // the start's recomputations are the start's
  const IterationEnd end = iterate_to_end(iteration, options_, ranks_.get());
  ContactResult result = iteration.result(end.status, end.iterations, options_.compute_approach);
  result.timings = iteration.timings();
  result.timings.start = start_seconds;
  result.timings.total = detail::seconds_since(solve_start);
  result.operator_applications += scale_applications + std::exchange(pending_applications_, 0);
  result.coarse_applications = nested.coarse_applications;
  detail::unscale(result, s, value, ranks_.get());
  result.warning = describe(result, options_.tolerance);
  return result;
}

}  // namespace coatfft
