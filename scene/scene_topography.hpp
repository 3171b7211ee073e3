#pragma once
// A scene on a measured topography ([contact] topography = "FILE"; docs/measured_surfaces.md):
// the file is read before the grid, whose keys it may supply, and becomes the gap of a rigid flat.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/grid.hpp"
#include "core/types.hpp"
#include "surfaces/detrend.hpp"
#include "topography/topography.hpp"

namespace coatfft::scene {

struct SceneTopography {
  std::filesystem::path file;
  topography::Topography map;
};

/// [grid]'s keys on a measured topography: the file's point counts and size where the scene
/// gives none; a count the scene gives must equal the file's, a size agree with it to 1e-9
/// (the digits files print); a file without a size needs the scene's lx and ly.
struct TopographyGrid {
  std::int64_t nx = 0, ny = 0;
  double lx = 0.0, ly = 0.0;
};
TopographyGrid topography_grid_keys(const SceneTopography& topography,
                                    std::optional<std::int64_t> nx, std::optional<std::int64_t> ny,
                                    std::optional<double> lx, std::optional<double> ly);

/// The gap max(z) - z of the topography as detrended on its own grid (surfaces/detrend.hpp) on
/// `grid`: the map in the middle, `pad` cells of the out-of-reach gap pad_gap() on each side; and
/// its report for summary.json: the file's summary (topography/topography_summary.hpp) with its
/// path, the pad and, on a periodic grid, the edge mismatch (surfaces/roughness.hpp) of the map.
struct TopographyGap {
  Field gap;
  nlohmann::json report;
};
TopographyGap topography_gap(const SceneTopography& topography, const Grid& grid, Detrend detrend,
                             bool periodic, std::int64_t pad = 0);

/// The gap [m] of the pad around a map whose largest gap is `max_gap`, on a map lx by ly: twice
/// the largest gap (at least the map's size), beyond any approach the map's own contact takes
/// until it is complete; the run checks that no pad cell was reached.
double pad_gap(double max_gap, double lx, double ly);

/// Whether `pressure` on `grid` is positive on a cell of the pad (`pad` cells along each side),
/// and on a border cell of the map inside it.
struct PadContact {
  bool pad = false;
  bool map_edge = false;
};
PadContact pad_contact(const Field& pressure, std::int64_t pad);

}  // namespace coatfft::scene
