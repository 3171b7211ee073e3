#pragma once
// Private to the scene layer: [method], how the displacements are computed.
#include <toml++/toml.h>

#include <filesystem>

#include "scene/scene.hpp"

namespace coatfft::scene {

// [method]: its keys into a MethodRequest, checked by method_from_request as Python's keywords are.
MethodSpec read_method(const toml::table& root, const std::filesystem::path& scene_dir,
                       Boundary boundary);

}  // namespace coatfft::scene
