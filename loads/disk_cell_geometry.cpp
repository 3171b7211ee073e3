#include "loads/detail/disk_cell_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace coatfft::detail {

double min_radius(const ScaledCell& c) {
  const double x = std::clamp(0.0, c.x0, c.x1);
  const double y = std::clamp(0.0, c.y0, c.y1);
  return std::hypot(x, y);
}

double max_radius(const ScaledCell& c) {
  const double x = std::max(std::abs(c.x0), std::abs(c.x1));
  const double y = std::max(std::abs(c.y0), std::abs(c.y1));
  return std::hypot(x, y);
}

std::vector<double> chord_breakpoints(const ScaledCell& c) {
  const double lo = std::max(c.x0, -1.0);
  const double hi = std::min(c.x1, 1.0);
  std::vector<double> b;
  if (!(lo < hi)) return b;
  b.push_back(lo);
  for (const double y : {c.y0, c.y1}) {
    if (std::abs(y) < 1.0) {
      const double xc = std::sqrt((1.0 - y) * (1.0 + y));
      for (const double x : {-xc, xc})
        if (x > lo && x < hi) b.push_back(x);
    }
  }
  b.push_back(hi);
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

}  // namespace coatfft::detail
