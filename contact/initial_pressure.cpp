#include "contact/initial_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace coatfft::detail {

Field hertzian_profile(const Field& h, double level) {
  return (level - h).max(0.0).sqrt();
}

double level_below(const Field& h, double share) {
  std::vector<double> values(h.data(), h.data() + h.size());
  const auto k = static_cast<std::ptrdiff_t>(share * static_cast<double>(values.size()));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

double level_correction(const Field& h, const Field& p, const Field& u) {
  const auto support = p > 0;
  const auto n = static_cast<double>(support.count());
  const double h_mean = support.select(h, 0.0).sum() / n;
  const double u_mean = support.select(u, 0.0).sum() / n;
  const double covariance = support.select((h - h_mean) * (u - u_mean), 0.0).sum();
  const double variance = support.select((h - h_mean).square(), 0.0).sum();
  const double slope = -covariance / variance;
  return std::isfinite(slope) && slope > 0 ? std::cbrt(slope * slope) : 1.0;
}

}  // namespace coatfft::detail
