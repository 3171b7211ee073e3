#include "core/grid.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace coatfft {

Grid::Grid(std::ptrdiff_t nx, std::ptrdiff_t ny, double lx, double ly)
    : nx_(nx), ny_(ny), lx_(lx), ly_(ly) {
  COATFFT_REQUIRE(nx >= 1 && nx <= max_cells_per_axis, "Grid: nx = ", nx,
                  ", but nx must be in [1, ", max_cells_per_axis, "]");
  COATFFT_REQUIRE(ny >= 1 && ny <= max_cells_per_axis, "Grid: ny = ", ny,
                  ", but ny must be in [1, ", max_cells_per_axis, "]");
  COATFFT_REQUIRE(std::isfinite(lx) && lx > 0, "Grid: lx = ", lx,
                  " m, but lx must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(ly) && ly > 0, "Grid: ly = ", ly,
                  " m, but ly must be finite and > 0");
  // The kernels form products and squares of lengths (r^2 = x^2 + y^2, cell areas dx dy): within
  // these bounds every such product of a domain and a cell length stays inside double precision.
  COATFFT_REQUIRE(lx >= min_length && lx <= max_length && ly >= min_length && ly <= max_length,
                  "Grid: lx = ", lx, " m, ly = ", ly, " m, but the domain lengths must lie in [",
                  min_length, ", ", max_length, "] m (rescale the units)");
}

void require_load_radius(const Grid& grid, double radius, std::string_view key) {
  const double half_domain = 0.5 * std::min(grid.lx(), grid.ly());
  COATFFT_REQUIRE(std::isfinite(radius) && radius > 0 && radius <= half_domain, key, " = ", radius,
                  " m must be finite and > 0, and at most half the domain (", half_domain, " m)");
}

namespace detail {

void require_rows(const Grid& grid, std::ptrdiff_t y0, std::ptrdiff_t rows, std::string_view who) {
  COATFFT_REQUIRE(y0 >= 0 && rows >= 0 && y0 + rows <= grid.ny(), who, ": rows ", y0, " to ",
                  y0 + rows, " are not rows of the grid (ny = ", grid.ny(), ")");
}

}  // namespace detail

}  // namespace coatfft
