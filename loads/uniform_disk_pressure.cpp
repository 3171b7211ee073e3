#include "loads/uniform_disk_pressure.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "loads/detail/disk_cell_geometry.hpp"

namespace coatfft {
namespace {

// Primitive of the half-chord c(x) = sqrt(1 - x^2): (x c + asin x) / 2, for |x| <= 1.
double half_chord_primitive(double x) {
  x = std::clamp(x, -1.0, 1.0);
  return 0.5 * (x * std::sqrt((1.0 - x) * (1.0 + x)) + std::asin(x));
}

// Exact area of the unit disk inside the cell: integrate the clipped chord
// [max(y0, -c), min(y1, c)] piece by piece; on a piece each end is either a cell side (constant)
// or the circle (+-c, integrated with the primitive above), so every piece is closed form.
double disk_area_in_cell(const detail::ScaledCell& cell) {
  const auto b = detail::chord_breakpoints(cell);
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < b.size(); ++k) {
    const double xl = b[k], xr = b[k + 1];
    const double xm = 0.5 * (xl + xr);
    const double cm = std::sqrt((1.0 - xm) * (1.0 + xm));
    const bool top_is_side = cell.y1 < cm;
    const bool bottom_is_side = cell.y0 > -cm;
    const double top = top_is_side ? cell.y1 : cm;
    const double bottom = bottom_is_side ? cell.y0 : -cm;
    if (top <= bottom) continue;  // the chord misses the cell on this whole piece
    const double c_int = half_chord_primitive(xr) - half_chord_primitive(xl);
    const double top_int = top_is_side ? cell.y1 * (xr - xl) : c_int;
    const double bottom_int = bottom_is_side ? cell.y0 * (xr - xl) : -c_int;
    area += top_int - bottom_int;
  }
  return area;
}

}  // namespace

Field uniform_disk_pressure(const Grid& grid, double p, double a, Sampling sampling) {
  return uniform_disk_pressure_rows(grid, p, a, sampling, 0, grid.ny());
}

Field uniform_disk_pressure_rows(const Grid& grid, double p, double a, Sampling sampling,
                                 std::ptrdiff_t y0, std::ptrdiff_t rows) {
  COATFFT_REQUIRE(std::isfinite(p), "uniform_disk_pressure: p = ", p, " Pa, but p must be finite");
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "uniform_disk_pressure: a = ", a,
                  " m, but the disk radius must be finite and > 0");
  detail::require_rows(grid, y0, rows, "uniform_disk_pressure");
  Field out = Field::Zero(grid.nx(), rows);
  const double hx = 0.5 * grid.dx() / a, hy = 0.5 * grid.dy() / a;
  for (std::ptrdiff_t j = y0; j < y0 + rows; ++j) {
    const double yc = grid.y(j) / a;
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double xc = grid.x(i) / a;
      if (sampling == Sampling::centre) {
        const double r2 = xc * xc + yc * yc;
        out(i, j - y0) = r2 < 1.0 ? p : (r2 == 1.0 ? 0.5 * p : 0.0);
        continue;
      }
      const detail::ScaledCell cell{xc - hx, xc + hx, yc - hy, yc + hy};
      if (detail::min_radius(cell) >= 1.0) continue;
      if (detail::max_radius(cell) <= 1.0) {
        out(i, j - y0) = p;
        continue;
      }
      out(i, j - y0) = p * disk_area_in_cell(cell) / (4.0 * hx * hy);
    }
  }
  return out;
}

}  // namespace coatfft
