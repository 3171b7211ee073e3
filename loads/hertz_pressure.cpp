#include "loads/hertz_pressure.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>

#include "core/error.hpp"
#include "loads/detail/disk_cell_geometry.hpp"

namespace coatfft {
namespace {

// Relative tolerance of the x quadrature; tanh-sinh converges double-exponentially on each
// piece, including the sqrt-type endpoint behaviour where the circle meets a cell side.
constexpr double x_tolerance = 1e-14;

// Primitive in y of sqrt(c^2 - y^2) for |y| <= c: (y sqrt(c^2 - y^2) + c^2 asin(y / c)) / 2.
// The root is formed as sqrt((c - y)(c + y)): with c^2 - y^2 a rounding residue of ~1e-17 at
// y = c would become ~1e-9 under the square root.
double chord_primitive(double y, double c) {
  y = std::clamp(y, -c, c);
  return 0.5 * (y * std::sqrt((c - y) * (c + y)) + c * c * std::asin(y / c));
}

// \int_{y0}^{y1} sqrt(1 - x^2 - y^2)_+ dy in closed form (unit radius, scaled coordinates).
double column_integral(double x, double y0, double y1) {
  const double c2 = (1.0 - x) * (1.0 + x);
  if (c2 <= 0.0) return 0.0;
  const double c = std::sqrt(c2);
  const double lo = std::max(y0, -c), hi = std::min(y1, c);
  if (hi <= lo) return 0.0;
  return chord_primitive(hi, c) - chord_primitive(lo, c);
}

// \iint_cell sqrt(1 - r^2)_+ dx dy: closed form in y, tanh-sinh in x on the pieces where the
// clipped chord keeps its form (split at the breakpoints so each integrand is analytic inside).
double hertz_integral_in_cell(const detail::ScaledCell& cell,
                              boost::math::quadrature::tanh_sinh<double>& quad) {
  const auto b = detail::chord_breakpoints(cell);
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < b.size(); ++k) {
    // Integrate over t in [-1/4, 1/4], x = centre + 2 (b - a) t: Boost 1.74's tanh_sinh
    // resolves the end points through their complements only when both ends are < 1/2 in
    // magnitude; otherwise it rounds abscissae onto them (and asserts in debug builds).
    const double xm = 0.5 * (b[k] + b[k + 1]), w = b[k + 1] - b[k];
    auto f = [&](double t) { return column_integral(xm + 2.0 * w * t, cell.y0, cell.y1); };
    sum += 2.0 * w * quad.integrate(f, -0.25, 0.25, x_tolerance);
  }
  return sum;
}

}  // namespace

Field hertz_pressure(const Grid& grid, double p0, double a, Sampling sampling) {
  return hertz_pressure_rows(grid, p0, a, sampling, 0, grid.ny());
}

Field hertz_pressure_rows(const Grid& grid, double p0, double a, Sampling sampling,
                          std::ptrdiff_t y0, std::ptrdiff_t rows) {
  COATFFT_REQUIRE(std::isfinite(p0), "hertz_pressure: p0 = ", p0, " Pa, but p0 must be finite");
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "hertz_pressure: a = ", a,
                  " m, but the contact radius must be finite and > 0");
  detail::require_rows(grid, y0, rows, "hertz_pressure");
  Field out = Field::Zero(grid.nx(), rows);
  const double hx = 0.5 * grid.dx() / a, hy = 0.5 * grid.dy() / a;
  if (sampling == Sampling::centre) {
    for (std::ptrdiff_t j = y0; j < y0 + rows; ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
        const double x = grid.x(i) / a, y = grid.y(j) / a;
        const double s = (1.0 - x * x - y * y);
        out(i, j - y0) = s > 0.0 ? p0 * std::sqrt(s) : 0.0;
      }
    return out;
  }
  boost::math::quadrature::tanh_sinh<double> quad;
  for (std::ptrdiff_t j = y0; j < y0 + rows; ++j) {
    const double yc = grid.y(j) / a;
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double xc = grid.x(i) / a;
      const detail::ScaledCell cell{xc - hx, xc + hx, yc - hy, yc + hy};
      if (detail::min_radius(cell) >= 1.0) continue;
      double integral;
      if (1.0 - detail::max_radius(cell) >= 8.0 * hx) {
        // Well inside the circle the x integrand is analytic on the cell: its nearest
        // singularity (where the half-chord meets a cell side) lies >= (1 - r_max)/2 >= 4 hx
        // beyond the interval of half-width hx, so the Bernstein ellipse has rho >= 4 + sqrt(15)
        // and 10-point Gauss-Legendre errs by ~rho^-20 ~ 1e-18: exact to round-off, ~10x
        // cheaper than tanh-sinh on the bulk of the cells.
        integral = boost::math::quadrature::gauss<double, 10>::integrate(
            [&](double x) { return column_integral(x, cell.y0, cell.y1); }, cell.x0, cell.x1);
      } else {
        integral = hertz_integral_in_cell(cell, quad);
      }
      out(i, j - y0) = p0 * integral / (4.0 * hx * hy);
    }
  }
  return out;
}

}  // namespace coatfft
