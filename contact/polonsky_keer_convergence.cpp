#include <algorithm>
#include <cmath>

#include "contact/complementarity.hpp"
#include "contact/detail/cell_passes.hpp"
#include "contact/detail/polonsky_keer_iteration.hpp"
#include "contact/detail/solver_ranks.hpp"

namespace coatfft::detail {

// The discrete complementarity conditions on every cell, for the gap update_gap left (u exact):
// p >= 0 (and p <= cap) hold by the projection; g >= -eps where p = 0, |g| <= eps where
// 0 < p < cap (p g = 0), and under a cap g <= eps where p = cap (the overlap there is plastic).
// eps is detail::gap_tolerance (docs/contact.md, "Convergence").
bool PolonskyKeerIteration::complementary(double tolerance) {
  const double* hd = h_.data();
  const double* pd = p_.data();
  const double* ud = capped_ ? u_.data() : nullptr;
  const double* gd = g_.data();
  const double* vd = v_.size() > 0 ? v_.data() : nullptr;
  const double s = scale_;
  const double cap = cap_;
  struct Maxima {
    double u = 0.0, h = 0.0, violation = 0.0;
    Maxima& operator+=(const Maxima& o) {
      u = std::max(u, o.u);
      h = std::max(h, o.h);
      violation = std::max(violation, o.violation);
      return *this;
    }
  };
  const Maxima maxima = detail::over_ranks(
      ranks_, over_cells<Maxima>(n_cells_, workers_, [&](auto first, auto last, Maxima& m) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double g = gd[k] - g_mean_;
          // The displacement: without a cap g = h + u - delta holds it.
          const double u = ud ? s * ud[k] + (vd ? vd[k] : 0.0) : gd[k] - hd[k] + delta_;
          m.u = std::max(m.u, std::abs(u));
          m.h = std::max(m.h, std::abs(hd[k]));
          m.violation = std::max(m.violation, pd[k] >= cap ? g : pd[k] > 0 ? std::abs(g) : -g);
        }
      }));
  const double u_max = maxima.u;
  const double largest_term = maxima.h + u_max + std::abs(delta_ + g_mean_);
  return maxima.violation <= detail::gap_tolerance(tolerance, u_max, largest_term);
}

}  // namespace coatfft::detail
