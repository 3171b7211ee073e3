#pragma once
// Named engineering materials for scene files ("steel", "tin", ...). Values are typical
// room-temperature properties; each entry in catalog.cpp cites its source.
#include <string>
#include <string_view>
#include <vector>

#include "material.hpp"

namespace coatfft {

/// The material registered under `name` (lower case, e.g. "steel"); throws InvalidArgument
/// listing the known names when there is none.
Material material_by_name(std::string_view name);

/// All registered names, in catalogue order.
std::vector<std::string> material_names();

}  // namespace coatfft
