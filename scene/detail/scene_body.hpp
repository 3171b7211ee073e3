#pragma once
// Private to the scene layer: the body, as layers ([substrate] and [[coating]]) or as a table of
// its FRF ([frf]).
#include <toml++/toml.h>

#include <filesystem>
#include <optional>

#include "layers/layer_stack.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

// [substrate] and [[coating]]: the layer stack.
LayerStack read_body(const toml::table& root);

// [substrate] is required, unless [frf] gives the body as a table and no stack is described.
std::optional<LayerStack> read_optional_body(const toml::table& root);

// [frf]: the body as a table of its FRF. Love's coefficients (direct, dcfft) need a material,
// which a table does not give, so those methods are refused here rather than when building.
void read_frf(const toml::table& root, const std::filesystem::path& scene_dir, Scene& scene);

}  // namespace coatfft::scene
