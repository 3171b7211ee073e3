#include "core/grid.hpp"

#include <cmath>

#include "core/error.hpp"

namespace coatfft {

Grid::Grid(std::ptrdiff_t nx, std::ptrdiff_t ny, double lx, double ly)
    : nx_(nx), ny_(ny), lx_(lx), ly_(ly) {
  COATFFT_REQUIRE(nx >= 1, "Grid: nx = ", nx, ", but nx must be >= 1");
  COATFFT_REQUIRE(ny >= 1, "Grid: ny = ", ny, ", but ny must be >= 1");
  COATFFT_REQUIRE(std::isfinite(lx) && lx > 0, "Grid: lx = ", lx,
                  " m, but lx must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(ly) && ly > 0, "Grid: ly = ", ly,
                  " m, but ly must be finite and > 0");
}

}  // namespace coatfft
