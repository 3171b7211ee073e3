#include "scene/scene_topography.hpp"

#include <cmath>

#include "core/error.hpp"
#include "surfaces/roughness.hpp"
#include "topography/topography_summary.hpp"

namespace coatfft::scene {

namespace {
template <typename T>
T agreed(const std::optional<T>& given, const std::optional<T>& in_file, const char* key,
         const SceneTopography& t) {
  if (!in_file) {
    COATFFT_REQUIRE(given.has_value(), "[grid] ", key, ": the topography ", t.file.string(),
                    " carries no size; give [grid] lx and ly");
    return *given;
  }
  if (given) {
    const bool same = std::is_integral_v<T> ? *given == *in_file
                                            : std::abs(double(*given - *in_file)) <=
                                                  1e-9 * std::abs(double(*in_file));
    COATFFT_REQUIRE(same, "[grid] ", key, " = ", *given, " disagrees with the topography ",
                    t.file.string(), ", whose ", key, " is ", *in_file,
                    " (leave it out to take the file's)");
  }
  return *in_file;
}
}  // namespace

TopographyGrid topography_grid_keys(const SceneTopography& t, std::optional<std::int64_t> nx,
                                    std::optional<std::int64_t> ny, std::optional<double> lx,
                                    std::optional<double> ly) {
  const std::optional<std::int64_t> file_nx = t.map.heights.rows(), file_ny = t.map.heights.cols();
  return {agreed(nx, file_nx, "nx", t), agreed(ny, file_ny, "ny", t), agreed(lx, t.map.lx, "lx", t),
          agreed(ly, t.map.ly, "ly", t)};
}

TopographyGap topography_gap(const SceneTopography& t, const Grid& grid, Detrend detrend,
                             bool periodic) {
  const Field heights = detrended(grid, t.map.heights, detrend);
  TopographyGap out{gap_of_topography(heights),
                    topography::topography_summary(t.map, heights, detrend)};
  // The scene's grid, not the file's, sizes the map now.
  out.report["file"] = t.file.string();
  out.report["lx"] = grid.lx();
  out.report["ly"] = grid.ly();
  out.report["rms_slope"] = rms_slope(grid, heights, periodic);
  out.report["edge_mismatch"] = nullptr;
  if (periodic) {
    const EdgeMismatch m = edge_mismatch(heights);
    out.report["edge_mismatch"] = {{"rms_jump", m.rms_jump},
                                   {"rms_step", m.rms_step},
                                   {"ratio", m.rms_step > 0 ? m.rms_jump / m.rms_step : 0.0}};
  }
  return out;
}

}  // namespace coatfft::scene
