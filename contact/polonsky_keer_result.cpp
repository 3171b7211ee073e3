#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "contact/complementarity.hpp"
#include "contact/detail/cell_passes.hpp"
#include "contact/detail/polonsky_keer_iteration.hpp"
#include "contact/detail/solver_ranks.hpp"

namespace coatfft::detail {

namespace {

// Whether a cell on the grid's border carries pressure; with ranks, p is this rank's rows, whose
// first and last are the grid's only on the first and last rank.
bool pressure_on_border(const Field& p, const SolverRanks* r, std::ptrdiff_t ny) {
  const auto nx = p.rows();
  const auto rows = p.cols();
  const bool first = r == nullptr || r->first_row() == 0;
  const bool last = r == nullptr || r->first_row() + r->rows() == ny;
  const bool mine =
      rows > 0 && ((p.row(0) > 0).any() || (p.row(nx - 1) > 0).any() ||
                   (first && (p.col(0) > 0).any()) || (last && (p.col(rows - 1) > 0).any()));
  return !detail::all_over(r, !mine);
}

}  // namespace

ContactResult PolonskyKeerIteration::result(ContactStatus status, int iterations,
                                            bool compute_approach) {
  if (!exact_) recompute_displacement();
  // The fields the result does not need are freed, and its own take the others' (the peak of a
  // solve's memory stays the iteration's: docs/scale.md, "Memory per cell").
  r_ = Field();
  g_prev_ = SingleField();
  cell_sets_ = ByteMask();
  // The displacement of s p in a field the iteration no longer needs: under a cap its two parts;
  // otherwise K p applied once more into t's field (g - h + delta would carry the rounding of
  // the heights, which can be many times the displacement's).
  const double s = scale_;
  p_ *= s;
  scale_ = 1.0;
  Field u;
  if (capped_) {
    u_ *= s;
    if (v_.size() > 0) u_ += v_;
    u = std::move(u_);
  } else {
    u = std::move(t_);
    op_.apply(p_, u);
    ++applications_;
  }
  const Mask contact = p_ > 0;
  const auto n_contact = detail::count_over(ranks_, contact.count());
  // The approach is the mean of h + u over the cells below the cap (at it, h + u exceeds the
  // approach by the plastic depth); over the carrying cells when all are at the cap.
  const Mask free = contact && p_ < cap_;
  const auto n_free = detail::count_over(ranks_, free.count());
  ContactResult result;
  result.control = control_;
  result.gap = std::move(g_);  // h + u first, in g's field
  result.gap = h_ + u;
  double approach = delta_;
  if (load_control_) {
    approach = n_free > 0      ? masked_mean(result.gap, free, n_free, ranks_)
               : n_contact > 0 ? masked_mean(result.gap, contact, n_contact, ranks_)
                               : detail::extrema_over(ranks_, h_).min;
  }
  result.gap -= approach;
  result.pressure = std::move(p_);
  result.displacement = std::move(u);
  result.load = detail::sum_over(ranks_, result.pressure.sum()) * cell_area_;
  if (!load_control_ || compute_approach) result.approach = approach;
  result.contact_area = static_cast<double>(n_contact) * cell_area_;
  if (n_contact > 0) result.contact_radius = std::sqrt(result.contact_area / std::numbers::pi);
  result.max_pressure = detail::extrema_over(ranks_, result.pressure).max;
  result.iterations = iterations;
  result.operator_applications = applications_;
  result.residual = residual_;
  result.status = status;
  result.converged = status == ContactStatus::converged;
  // A periodic surface has no edge: a contact crossing the period's border is just a contact.
  result.touches_boundary =
      !op_.periodic() && pressure_on_border(result.pressure, ranks_, op_.grid().ny());
  if (!capped_) {
    result.max_penetration = ranks_ ? std::max(0.0, -detail::extrema_over(ranks_, result.gap).min)
                                    : max_penetration(result.gap);
    return result;
  }
  // Under a cap the overlap of the cells at it is plastic depth, not a penetration.
  const Mask plastic = result.pressure >= cap_;
  result.max_penetration =
      std::max(0.0, -detail::extrema_over(ranks_, plastic.select(0.0, result.gap).eval()).min);
  result.plastic_depth = plastic.select((-result.gap).max(0.0), 0.0);
  return result;
}

}  // namespace coatfft::detail
