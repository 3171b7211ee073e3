#include <algorithm>
#include <memory>
#include <optional>

#include "contact/contact_solver.hpp"
#include "contact/detail/contact_patches.hpp"
#include "contact/detail/grid_transfer.hpp"
#include "contact/detail/initial_pressure.hpp"
#include "contact/detail/solver_ranks.hpp"

namespace coatfft {

// Nested start: the coarse problem is the same contact on the coarse operator (the Galerkin
// product R K P) with the heights' 2 x 2 means R h and the same load or approach; its pressure,
// carried to the fine cells, starts the fine iteration near its solution, so the fine grid spends
// its iterations on what the coarse one cannot resolve (docs/contact.md, "Nested start"). Only
// where the heights below the trial level form more than one patch (a rough surface).
ContactSolver::NestedStart ContactSolver::nested_start(const Field& h, ContactControl control,
                                                       double value) {
  constexpr std::ptrdiff_t coarsest = 64;    // cells per side of the coarsest grid
  constexpr double coarse_tolerance = 1e-3;  // a start needs no more (docs/contact.md)
  const Grid& grid = op_.grid();
  if (!options_.nested_start || grid.nx() % 2 != 0 || grid.ny() % 2 != 0 ||
      std::min(grid.nx(), grid.ny()) < 2 * coarsest)
    return {};
  // One patch below the trial level (a smooth indenter) is what the Hertzian start describes
  // nearly exactly: there the coarse solves would cost more than they spare (docs/contact.md).
  const detail::SolverRanks* ranks = ranks_.get();
  const double level = detail::level_below(h, detail::kTrialContactShare, ranks);
  if (detail::count_patches(h < level, op_.periodic(), ranks) <= 1) return {};
  // Distributed fields: each rank's pairs of rows, when they pair up (coarsened() says).
  Field h_coarse = detail::restrict_by_mean(h);
  // The means' minimum lies above min(h): an approach just beyond min(h) may miss them.
  if (control == ContactControl::approach && !(value > detail::extrema_over(ranks, h_coarse).min))
    return {};
  const std::unique_ptr<SurfaceOperator> coarse = op_.coarsened();
  if (!coarse) return {};
  NestedStart nested;
  nested.applications = 1;  // coarsened()'s unit response
  ContactOptions options = options_;
  options.tolerance = std::max(options_.tolerance, coarse_tolerance);
  options.compute_approach = false;
  options.on_iteration = nullptr;
  options.preconditioner_planning = Planning::estimate;  // a few cheap iterations
  ContactSolver solver(*coarse, options, ranks ? ranks->of(*coarse) : nullptr);
  const ContactResult result = solver.solve(h_coarse, control, value);
  nested.coarse_applications = result.operator_applications + result.coarse_applications;
  if (detail::sum_over(ranks, result.pressure.sum()) > 0)
    nested.pressure = detail::prolong_by_cell(result.pressure);
  return nested;
}

}  // namespace coatfft
