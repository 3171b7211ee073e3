#include "topography/topography_summary.hpp"

#include <cmath>

#include "core/error.hpp"
#include "surfaces/roughness.hpp"

namespace coatfft::topography {

namespace {
// One axis of the map as a grid takes it: its count of points and its size [m].
void require_grid_axis(const std::filesystem::path& file, const char* axis, Eigen::Index n,
                       double length, bool sized) {
  COATFFT_REQUIRE(n <= Grid::max_cells_per_axis, file.string(), ": ", n, " points along ", axis,
                  ", more than the ", Grid::max_cells_per_axis, " a grid takes");
  if (!sized) return;
  COATFFT_REQUIRE(std::isfinite(length) && length >= Grid::min_length && length <= Grid::max_length,
                  file.string(), ": the spacing ", length / static_cast<double>(n), " m along ",
                  axis, " makes the map ", length, " m long, outside the [", Grid::min_length, ", ",
                  Grid::max_length, "] m a grid takes (is the unit right?)");
}
}  // namespace

Grid topography_grid(const std::filesystem::path& file, const Topography& t) {
  const auto nx = t.heights.rows(), ny = t.heights.cols();
  require_grid_axis(file, "x", nx, t.lx.value_or(0.0), t.lx.has_value());
  require_grid_axis(file, "y", ny, t.ly.value_or(0.0), t.ly.has_value());
  return Grid(nx, ny, t.lx.value_or(static_cast<double>(nx)),
              t.ly.value_or(static_cast<double>(ny)));
}

void require_finite_map(const std::filesystem::path& file, const Field& map,
                        std::string_view what) {
  COATFFT_REQUIRE(map.allFinite(), file.string(), ": ", what,
                  " overflows (the heights reach beyond the largest double when subtracted)");
}

nlohmann::json topography_summary(const std::filesystem::path& file, const Topography& t,
                                  const Field& heights, Detrend detrend,
                                  const std::optional<Grid>& sized, bool periodic) {
  using nlohmann::json;
  const char* detrends[] = {"none", "mean", "plane"};
  json out = {{"format", t.format},
              {"nx", t.heights.rows()},
              {"ny", t.heights.cols()},
              {"lx", sized ? json(sized->lx()) : json()},
              {"ly", sized ? json(sized->ly()) : json()},
              {"unit", t.unit.empty() ? json() : json(t.unit)},
              {"periodic", t.periodic ? json(*t.periodic) : json()},
              {"missing", t.missing},
              {"detrend", detrends[static_cast<int>(detrend)]},
              {"rms_height", rms_height(heights)},
              {"rms_slope", json()},
              {"min", heights.minCoeff()},
              {"max", heights.maxCoeff()}};
  if (sized) {
    const double slope = rms_slope(*sized, heights, periodic);
    COATFFT_REQUIRE(std::isfinite(slope), file.string(),
                    ": the rms slope of the heights is beyond the largest double");
    out["rms_slope"] = slope;
  }
  json metadata = json::object();
  for (const auto& [name, value] : t.metadata) metadata[name] = value;
  out["metadata"] = metadata;
  return out;
}

}  // namespace coatfft::topography
