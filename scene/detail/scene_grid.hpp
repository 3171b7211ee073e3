#pragma once
// Private to the scene layer: [grid], on a measured topography ([contact] topography = "FILE",
// read first) or refined for the load (refine = "auto").
#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <optional>

#include "core/grid.hpp"
#include "scene/scene.hpp"
#include "scene/scene_topography.hpp"

namespace coatfft::scene {

// [grid]: nx and ny, or refine = "auto" with tolerance_total (the grid is then chosen once the
// load and the body are known: refine_grid).
struct GridSection {
  double lx = 0.0;
  double ly = 0.0;
  std::optional<Grid> grid;               // nx and ny given
  std::optional<double> tolerance_total;  // refine = "auto"
  Boundary boundary = Boundary::free;     // [grid] boundary
  std::int64_t pad = 0;                   // a topography's pad [cells each side]
};

// [contact] topography = "FILE" with its unit and missing keys, read before the grid (whose keys
// the file may give); the keys are read again, and checked with the others, by read_contact.
std::optional<SceneTopography> read_scene_topography(const toml::table& root,
                                                     const std::filesystem::path& scene_dir,
                                                     std::optional<double> max_memory);

// [grid] of `root`, on the measured `topography` (null without one).
GridSection read_grid(const toml::table& root, const SceneTopography* topography);

// refine = "auto": the grid on which the load's discretisation error is within tolerance_total
// less the operator's tolerance ([method] tolerance, by default a tenth of tolerance_total).
Grid refine_grid(const toml::table& root, const GridSection& g, Scene& scene);

}  // namespace coatfft::scene
