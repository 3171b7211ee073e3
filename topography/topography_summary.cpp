#include "topography/topography_summary.hpp"

#include "surfaces/roughness.hpp"

namespace coatfft::topography {

Grid topography_grid(const Topography& t) {
  const auto nx = t.heights.rows(), ny = t.heights.cols();
  return Grid(nx, ny, t.lx.value_or(static_cast<double>(nx)),
              t.ly.value_or(static_cast<double>(ny)));
}

nlohmann::json topography_summary(const Topography& t, const Field& heights, Detrend detrend,
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
  if (sized) out["rms_slope"] = rms_slope(*sized, heights, periodic);
  json metadata = json::object();
  for (const auto& [name, value] : t.metadata) metadata[name] = value;
  out["metadata"] = metadata;
  return out;
}

}  // namespace coatfft::topography
