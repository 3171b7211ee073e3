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

/// The gap max(z) - z of the topography as detrended on `grid` (surfaces/detrend.hpp), and its
/// report for summary.json: the file's summary (topography/topography_summary.hpp) with its path
/// and, on a periodic grid, the edge mismatch (surfaces/roughness.hpp) of the detrended map.
struct TopographyGap {
  Field gap;
  nlohmann::json report;
};
TopographyGap topography_gap(const SceneTopography& topography, const Grid& grid, Detrend detrend,
                             bool periodic);

}  // namespace coatfft::scene
