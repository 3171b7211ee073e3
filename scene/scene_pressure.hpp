#pragma once
// The known pressure of a [pressure] scene on its grid: read from its file (shape and values
// checked) or sampled from its closed form; a load that cannot be represented on the grid (all
// zero, or narrower than a cell and sampled at the centres) is refused.
#include <optional>

#include "core/types.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// The pressure [Pa] of `scene` (which has a [pressure] section) on its grid. Throws
/// InvalidArgument naming the key or the file.
Field scene_pressure(const Scene& scene);

/// The checks scene_pressure makes of the load it read or sampled: the disk's limits on the grid,
/// and `nonzero`, whether the pressure is not zero on some cell (a distributed run's, over its
/// ranks). Throws InvalidArgument naming the key or the file.
void require_load(const Scene& scene, bool nonzero);

/// Tangential tractions q_x, q_y [Pa] the surface receives; an absent one is zero.
struct Tractions {
  std::optional<Field> qx, qy;
};

/// The tractions of `scene` under `pressure`: [shear]'s (q = mu p along its direction, or its
/// files, shape and values checked), or [contact] friction's q_x = friction p. Throws
/// InvalidArgument naming the key or the file.
Tractions scene_tractions(const Scene& scene, const Field& pressure);

}  // namespace coatfft::scene
