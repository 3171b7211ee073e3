#pragma once
// The known pressure of a [pressure] scene on its grid: read from its file (shape and values
// checked) or sampled from its closed form; a load that cannot be represented on the grid (all
// zero, or narrower than a cell and sampled at the centres) is refused.
#include "cli/scene.hpp"
#include "core/types.hpp"

namespace coatfft::cli {

/// The pressure [Pa] of `scene` (which has a [pressure] section) on its grid. Throws
/// InvalidArgument naming the key or the file.
Field scene_pressure(const Scene& scene);

}  // namespace coatfft::cli
