#include <algorithm>
#include <cmath>

#include "contact/complementarity.hpp"
#include "contact/detail/cell_passes.hpp"
#include "contact/detail/polonsky_keer_iteration.hpp"
#include "contact/detail/solver_ranks.hpp"

namespace coatfft::detail {

// The discrete complementarity conditions on every cell, for the gap update_gap left (u exact):
// p >= 0 holds by the projection; g >= -eps where p = 0 and |g| <= eps where p > 0 (p g = 0).
// eps is detail::gap_tolerance (docs/contact.md, "Convergence").
bool PolonskyKeerIteration::complementary(double tolerance) {
  const double* hd = h_.data();
  const double* pd = p_.data();
  const double* ud = u_.data();
  const double* gd = g_.data();
  struct Maxima {
    double u = 0.0, h = 0.0, violation = 0.0;
    Maxima& operator+=(const Maxima& o) {
      u = std::max(u, o.u);
      h = std::max(h, o.h);
      violation = std::max(violation, o.violation);
      return *this;
    }
  };
  const Maxima m = detail::over_ranks(
      ranks_, over_cells<Maxima>(n_cells_, workers_, [&](auto first, auto last, Maxima& s) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double g = gd[k] - g_mean_;
          s.u = std::max(s.u, std::abs(ud[k]));
          s.h = std::max(s.h, std::abs(hd[k]));
          s.violation = std::max(s.violation, pd[k] > 0 ? std::abs(g) : -g);
        }
      }));
  const double u_max = scale_ * m.u;
  const double largest_term = m.h + u_max + std::abs(delta_ + g_mean_);
  return m.violation <= detail::gap_tolerance(tolerance, u_max, largest_term);
}

}  // namespace coatfft::detail
