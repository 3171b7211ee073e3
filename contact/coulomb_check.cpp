// The conditions of a partial-slip solution (contact/partial_slip.hpp, CoulombCheck), cell by cell.
#include <algorithm>
#include <cmath>

#include "contact/complementarity.hpp"
#include "contact/partial_slip.hpp"

namespace coatfft {

CoulombCheck check_coulomb(const Grid& grid, const Field& bound, const Field& qx, const Field& qy,
                           const Field& sx, const Field& sy, std::optional<double> load,
                           double slip_scale, double tolerance) {
  CoulombCheck c;
  const double limit = bound.maxCoeff();
  for (Eigen::Index k = 0; k < bound.size(); ++k) {
    const double q = std::hypot(qx(k), qy(k));
    if (bound(k) <= 0.0) {
      c.outside = std::max(c.outside, q);
      continue;
    }
    c.excess = std::max(c.excess, (q - bound(k)) / limit);
    // The slip is the friction's direction times its size: s = -|s| q/(mu p). A sticking cell
    // (|q| < mu p) must not slip, a slipping one must carry the limit against its slip.
    const double s = std::hypot(sx(k), sy(k));
    const double ex = sx(k) + s * qx(k) / bound(k), ey = sy(k) + s * qy(k) / bound(k);
    c.slip_error = std::max(c.slip_error, std::hypot(ex, ey));
  }
  if (load) {
    const double carried = qx.sum() * grid.dx() * grid.dy();
    c.load_error =
        std::abs(carried - *load) / (limit > 0.0 ? bound.sum() * grid.dx() * grid.dy() : 1.0);
  }
  // The slip is known to the accuracy of the displacement (as the gap of the normal problem).
  c.slip_scale = slip_scale;
  c.slip_bound = detail::gap_tolerance(tolerance, slip_scale, slip_scale);
  c.holds = c.excess <= tolerance && c.outside == 0.0 && c.slip_error <= c.slip_bound &&
            c.load_error <= tolerance;
  return c;
}

}  // namespace coatfft
