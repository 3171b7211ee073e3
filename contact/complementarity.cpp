#include "contact/complementarity.hpp"

#include <algorithm>
#include <limits>

namespace coatfft {

double max_penetration(const Field& gap) {
  return gap.size() == 0 ? 0.0 : std::max(0.0, -gap.minCoeff());
}

namespace detail {

double gap_tolerance(double tolerance, double u_max, double largest_term) {
  constexpr double ulps = 64 * std::numeric_limits<double>::epsilon();
  return tolerance * u_max + ulps * largest_term;
}

}  // namespace detail

}  // namespace coatfft
