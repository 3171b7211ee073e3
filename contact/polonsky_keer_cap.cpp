#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "contact/detail/cell_passes.hpp"
#include "contact/detail/polonsky_keer_iteration.hpp"
#include "contact/detail/solver_ranks.hpp"

// The hardness's part of the iteration (ContactOptions::hardness; docs/contact.md, "Hardness"):
// the start clipped to the cap, and under load control the load restored after each step. The
// elastic iteration restores it by scaling the whole pressure (enforce_load), which leaves u = K p
// exact for free; under a cap a scaled cell at the cap would leave it, so only the cells below
// the cap are scaled, u_ (their displacement) with them, and the cells the scaling lifts past
// the cap are clipped: the load is then f(s) = sum of min(cap, s p) over the cells, concave and
// non-decreasing in s, and Newton's method from below reaches its root without overshooting
// (each round clips at least one more cell, and f is linear between).

namespace coatfft::detail {

// The start (any of start()'s) clipped to the cap; from here on the displacement is held in its
// two parts (recomputed by the first step). Under load control the load is restored as after a
// step; where the start's cells cannot carry it at the cap, the load is spread over the domain
// (which the solver's check allows: load < cap times the domain's area).
void PolonskyKeerIteration::start_under_cap() {
  p_ = p_.min(cap_);
  v_ = zero_field(h_);
  exact_ = false;
  plastic_exact_ = false;
  if (!load_control_) return;
  std::optional<double> s = cap_scale(cap_sums());
  if (!s) {
    p_.setConstant(value_ /
                   (static_cast<double>(detail::count_over(ranks_, n_cells_)) * cell_area_));
    s = 1.0;
  }
  rescale_under_cap(*s, nullptr);
}

// The load (in the pressure's units, sum p) of min(cap, s p) and its slope in s.
PolonskyKeerIteration::CapLoad PolonskyKeerIteration::capped_load(double s) {
  const double* pd = p_.data();
  const double cap = cap_;
  return detail::over_ranks(
      ranks_, over_cells<CapLoad>(n_cells_, workers_, [&](auto first, auto last, CapLoad& sum) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          if (!(pd[k] > 0)) continue;
          const double sp = pd[k] >= cap ? cap : s * pd[k];
          if (sp >= cap) {
            sum.load += cap;
          } else {
            sum.load += sp;
            sum.slope += pd[k];
          }
        }
      }));
}

// project()'s sums of the current pressure, where no projection made them.
PolonskyKeerIteration::Projected PolonskyKeerIteration::cap_sums() {
  const double* pd = p_.data();
  const double cap = cap_;
  struct Sums {
    double p = 0.0, free = 0.0, free_max = 0.0;
    std::ptrdiff_t at_cap = 0;
    Sums& operator+=(const Sums& o) {
      p += o.p;
      free += o.free;
      free_max = std::max(free_max, o.free_max);
      at_cap += o.at_cap;
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& sum) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          sum.p += pd[k];
          if (pd[k] >= cap) {
            ++sum.at_cap;
          } else {
            sum.free += pd[k];
            sum.free_max = std::max(sum.free_max, pd[k]);
          }
        }
      }));
  return {sums.p, 0.0, sums.free, sums.free_max, sums.at_cap};
}

// The scale s of the cells below the cap that gives the load, or nothing when the cells that
// carry pressure cannot carry it even at the cap. Below zero (the cells at the cap alone carry
// more than the load) the caller scales every cell instead: returned as -1 times that factor.
std::optional<double> PolonskyKeerIteration::cap_scale(const Projected& sums) {
  const double target = value_ / cell_area_;
  const double rest = target - cap_ * static_cast<double>(sums.at_cap);
  if (rest < 0) return -target / sums.p_sum;
  if (!(sums.free_sum > 0)) {
    if (rest <= 4 * std::numeric_limits<double>::epsilon() * target) return 1.0;
    return std::nullopt;
  }
  double s = rest / sums.free_sum;
  if (s * sums.free_max <= cap_) return s;  // nothing clipped: the usual case
  constexpr int max_rounds = 1000;          // each clips a cell more; a few in practice
  for (int round = 0; round < max_rounds; ++round) {
    const CapLoad f = capped_load(s);
    if (f.load >= target * (1 - 4 * std::numeric_limits<double>::epsilon())) break;
    if (!(f.slope > 0)) return std::nullopt;
    const double next = s + (target - f.load) / f.slope;
    if (!(next > s)) break;
    s = next;
  }
  return s;
}

// Step 5 under a cap and load control: the load restored (the file's comment), in one pass that
// also measures the step's change exactly against the previous iterate. Where the cells that
// carry pressure cannot carry the load at the cap (a step cut too many), the iterate is taken
// halfway back to the previous one, whose cells could: their union can.
double PolonskyKeerIteration::restore_load_under_cap(Projected projected) {
  const double* previous = r_.data();  // project() swapped them; old_scale_ is 1 here
  std::optional<double> s = cap_scale(projected);
  if (!s) {
    p_ = 0.5 * (p_ + r_);
    exact_ = false;
    plastic_exact_ = false;
    s = cap_scale(cap_sums());
  }
  if (!s) s = 1.0;  // unreachable by the argument above; the iteration goes on regardless
  if (*s < 0) {
    scale_all_below_cap(-*s);
    s = 1.0;
  }
  return rescale_under_cap(*s, previous);
}

// Every cell scaled by s < 1, so that all end below the cap (the cells at it carried more than
// the load); the cells at the cap change, so both parts of the displacement are recomputed.
void PolonskyKeerIteration::scale_all_below_cap(double s) {
  p_ *= s;
  exact_ = false;
  plastic_exact_ = false;
}

// p <- min(cap, s p) on the cells below the cap, u_ (their displacement) scaled with them.
// Returns the relative change sum |p - previous| / sum p against `previous` (null: none).
double PolonskyKeerIteration::rescale_under_cap(double s, const double* previous) {
  double* pd = p_.data();
  double* ud = u_.data();
  const double cap = cap_;
  struct Sums {
    double p = 0.0, change = 0.0;
    bool clipped = false;
    Sums& operator+=(const Sums& o) {
      p += o.p;
      change += o.change;
      clipped = clipped || o.clipped;
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& sum) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          if (pd[k] > 0 && pd[k] < cap) {
            const double sp = s * pd[k];
            sum.clipped = sum.clipped || sp >= cap;
            pd[k] = std::min(cap, sp);
          }
          ud[k] *= s;
          sum.p += pd[k];
          if (previous) sum.change += std::abs(pd[k] - previous[k]);
        }
      }));
  if (sums.clipped) {
    exact_ = false;
    plastic_exact_ = false;
  }
  return sums.p > 0 ? sums.change / sums.p : std::numeric_limits<double>::infinity();
}

}  // namespace coatfft::detail
