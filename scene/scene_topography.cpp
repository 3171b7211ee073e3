#include "scene/scene_topography.hpp"

#include <algorithm>
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
  topography::topography_grid(t.file, t.map);  // refuses a map no grid holds, naming the file
  const std::optional<std::int64_t> file_nx = t.map.heights.rows(), file_ny = t.map.heights.cols();
  return {agreed(nx, file_nx, "nx", t), agreed(ny, file_ny, "ny", t), agreed(lx, t.map.lx, "lx", t),
          agreed(ly, t.map.ly, "ly", t)};
}

double pad_gap(double max_gap, double lx, double ly) {
  return 2.0 * max_gap + (max_gap > 0 ? 0.0 : std::max(lx, ly));
}

PadContact pad_contact(const Field& p, std::int64_t pad) {
  const Eigen::Index nx = p.rows() - 2 * pad, ny = p.cols() - 2 * pad;
  const auto map = p.block(pad, pad, nx, ny);
  const bool edge = (map.row(0) > 0).any() || (map.row(nx - 1) > 0).any() ||
                    (map.col(0) > 0).any() || (map.col(ny - 1) > 0).any();
  return {(p > 0).count() > (map > 0).count(), edge};
}

TopographyGap topography_gap(const SceneTopography& t, const Grid& grid, Detrend detrend,
                             bool periodic, std::int64_t pad) {
  const Eigen::Index nx = t.map.heights.rows(), ny = t.map.heights.cols();
  const Grid map_grid(nx, ny, grid.dx() * static_cast<double>(nx),
                      grid.dy() * static_cast<double>(ny));
  const Field heights = detrended(map_grid, t.map.heights, detrend);
  topography::require_finite_map(t.file, heights, "the detrended map");
  const Field map_gap = gap_of_topography(heights);
  topography::require_finite_map(t.file, map_gap, "the gap max(z) - z");
  TopographyGap out{Field::Constant(grid.nx(), grid.ny(),
                                    pad_gap(map_gap.maxCoeff(), map_grid.lx(), map_grid.ly())),
                    topography::topography_summary(t.file, t.map, heights, detrend, map_grid,
                                                   periodic && pad == 0)};
  out.gap.block(pad, pad, nx, ny) = map_gap;
  // The scene's grid, not the file's, sizes the map (lx, ly, rms_slope above); the slope crosses
  // the map's edges only where the map is its own periodic copy's neighbour.
  out.report["file"] = t.file.string();
  out.report["pad"] = pad;
  out.report["edge_mismatch"] = nullptr;
  if (periodic && pad == 0) {
    const EdgeMismatch m = edge_mismatch(heights);
    out.report["edge_mismatch"] = {{"rms_jump", m.rms_jump},
                                   {"rms_step", m.rms_step},
                                   {"ratio", m.rms_step > 0 ? m.rms_jump / m.rms_step : 0.0}};
  }
  return out;
}

}  // namespace coatfft::scene
