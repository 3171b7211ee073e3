#include "loads/load_limits.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace coatfft {

void require_disk_load(const Grid& grid, double amplitude, double radius, Sampling sampling,
                       const DiskLoadKeys& keys) {
  COATFFT_REQUIRE(std::isfinite(amplitude) && amplitude > 0, keys.amplitude, " = ", amplitude,
                  " Pa must be finite and > 0");
  require_load_radius(grid, radius, keys.radius);
  COATFFT_REQUIRE(sampling != Sampling::centre || 2.0 * radius >= std::max(grid.dx(), grid.dy()),
                  keys.radius, " = ", radius,
                  " m: the load is narrower than a cell (dx = ", grid.dx(), " m, dy = ", grid.dy(),
                  " m from ", keys.grid,
                  ") and is sampled at the cell centres; refine the grid or use sampling = "
                  "\"cell_average\"");
}

}  // namespace coatfft
