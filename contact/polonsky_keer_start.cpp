#include <cmath>

#include "contact/detail/cell_passes.hpp"
#include "contact/detail/initial_pressure.hpp"
#include "contact/detail/polonsky_keer_iteration.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "core/error.hpp"

namespace coatfft::detail {

// The initial pressure.
void PolonskyKeerIteration::start(bool warm) {
  if (warm) {
    p_ = p_.max(0.0);
    if (detail::sum_over(ranks_, p_.sum()) > 0) {
      start_from_pressure();
      return;
    }
  }
  if (update_by_linearity_) {
    start_hertzian();
  } else {
    start_uniform();
  }
}

// A warm start (a sweep, ContactSolver::solve_sweep): p_ holds the pressure of a neighbouring
// solve, scaled here to this one's load or approach (one application). Its contact set is close
// to this one's, which is what the iteration spends its recomputations on.
void PolonskyKeerIteration::start_from_pressure() {
  if (!load_control_) {
    // A neighbour's contact may lie wholly out of this approach's reach (a path of falling
    // approaches): then the usual start.
    if (!scale_to_approach()) update_by_linearity_ ? start_hertzian() : start_uniform();
    return;
  }
  p_ *= value_ / (detail::sum_over(ranks_, p_.sum()) * cell_area_);
  recompute_displacement();
}

// Polonsky & Keer's start: under load control the load spread uniformly over the whole domain;
// under approach control a uniform pressure on the geometric overlap {h < delta}, scaled to the
// approach (one application).
void PolonskyKeerIteration::start_uniform() {
  if (load_control_) {
    p_.setConstant(value_ /
                   (static_cast<double>(detail::count_over(ranks_, n_cells_)) * cell_area_));
    return;
  }
  p_ = (h_ < delta_).cast<double>();
  scale_to_approach();  // delta > h on the support: it scales
}

// A Hertzian start (initial_pressure.hpp): sqrt(level - h) on {h < level}. Under approach control
// the level is half the overlap, Hertz's; under load control it is fitted by one application.
void PolonskyKeerIteration::start_hertzian() {
  const detail::RankExtrema h_range = detail::extrema_over(ranks_, h_);
  const double h_min = h_range.min;
  if (!load_control_) {
    p_ = detail::hertzian_profile(h_, h_min + 0.5 * (delta_ - h_min));
    scale_to_approach();  // delta > h on the profile's support: it scales
    return;
  }
  double level = detail::level_below(h_, detail::kTrialContactShare, ranks_) - h_min;
  if (!(level > 0)) {  // a flat face holds a quarter of the cells: a level just above it
    const double h_max = h_range.max;
    level = h_max > h_min ? detail::kTrialContactShare * (h_max - h_min) : 1.0;
  }
  const auto carry_load = [&] {
    p_ = detail::hertzian_profile(h_, h_min + level);
    // A load whose displacements lie below the rounding of min(h) fits a level that h_min + level
    // cannot resolve: no cell is left, and the load rests on the lowest cells.
    if (!(detail::sum_over(ranks_, p_.sum()) > 0)) p_ = (h_ == h_min).cast<double>();
    p_ *= value_ / (detail::sum_over(ranks_, p_.sum()) * cell_area_);
  };
  carry_load();
  recompute_displacement();
  level *= detail::level_correction(h_, p_, displacement(), ranks_);
  carry_load();
  exact_ = false;
}

// Approach control: p scaled so that the mean gap over its support vanishes (one application).
// false, p left as it is, when the support lies beyond the approach's reach on average (the
// mean of delta - h not positive): no positive scale closes it.
bool PolonskyKeerIteration::scale_to_approach() {
  const Mask support = p_ > 0;
  const auto n_support = detail::count_over(ranks_, support.count());
  recompute_displacement();
  const double reach = masked_mean(delta_ - h_, support, n_support, ranks_);
  if (!(reach > 0)) return false;
  Field& u = displacement();
  const double scale = reach / masked_mean(u, support, n_support, ranks_);
  COATFFT_REQUIRE(std::isfinite(scale) && scale > 0, "ContactSolver: operator '", op_.name(),
                  "' returned a non-positive mean displacement under a positive pressure");
  p_ *= scale;
  u *= scale;
  return true;
}

}  // namespace coatfft::detail
