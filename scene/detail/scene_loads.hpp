#pragma once
// Private to the scene layer: the loads, a known [pressure] (with [shear]) or a [contact] with its
// indenter and its control.
#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>

#include "core/grid.hpp"
#include "layers/layer_stack.hpp"
#include "scene/scene.hpp"
#include "scene/scene_topography.hpp"

namespace coatfft::scene {

// What the sections after [grid] read against: the grid, its boundary, the scene's folder and a
// measured topography read before the grid (null without one).
struct SceneContext {
  const Grid& grid;
  bool periodic = false;
  const std::filesystem::path& scene_dir;
  const SceneTopography* topography = nullptr;
  std::int64_t pad = 0;           ///< [grid] pad of the topography
  bool height_map_values = true;  ///< SceneReading::height_map_values
};

// [pressure] of `table`, its disk checked against `grid` (the scene's, or only the domain of a
// refinement).
PressureSpec read_pressure(const toml::table& table, const Grid& grid,
                           const std::filesystem::path& scene_dir);

// [contact] of `table`. `stack_body`: the body the operator is built from when it is a stack,
// nullptr for a table.
ContactSpec read_contact(const toml::table& table, const SceneContext& context,
                         const LayerStack* stack_body);

// [shear]: tangential tractions with a known pressure.
ShearSpec read_shear(const toml::table& root, const std::filesystem::path& scene_dir);

}  // namespace coatfft::scene
