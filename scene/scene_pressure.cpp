#include "scene/scene_pressure.hpp"

#include "core/error.hpp"
#include "io/grid_file.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/load_limits.hpp"
#include "loads/uniform_disk_pressure.hpp"

namespace coatfft::scene {

namespace {

Field pressure_from_scene(const Scene& scene) {
  const PressureSpec& spec = *scene.pressure;
  switch (spec.kind) {
    case PressureKind::file:
      return io::read_grid_file(spec.file, scene.grid, "[pressure] path", "value");
    case PressureKind::hertz:
      return hertz_pressure(scene.grid, spec.amplitude, spec.radius, spec.sampling);
    case PressureKind::uniform_disk:
      return uniform_disk_pressure(scene.grid, spec.amplitude, spec.radius, spec.sampling);
  }
  throw InvalidArgument("[pressure] kind: unknown");
}

}  // namespace

// The disk's limits on the scene's final grid (loads/load_limits.hpp), and a pressure that is not
// zero everywhere.
void require_load(const Scene& scene, bool nonzero) {
  const PressureSpec& load = *scene.pressure;
  if (load.kind != PressureKind::file)
    require_disk_load(scene.grid, load.amplitude, load.radius, load.sampling,
                      {load.kind == PressureKind::hertz ? "[pressure] p0" : "[pressure] p",
                       "[pressure] a", "[grid] lx, ly, nx, ny"});
  COATFFT_REQUIRE(nonzero,
                  load.kind == PressureKind::file ? load.file.string() : std::string("[pressure]"),
                  ": the pressure is zero on every cell: nothing to compute");
}

Field scene_pressure(const Scene& scene) {
  Field pressure = pressure_from_scene(scene);
  require_load(scene, (pressure != 0.0).any());
  return pressure;
}

Tractions scene_tractions(const Scene& scene, const Field& pressure) {
  Tractions t;
  if (scene.contact && scene.contact->full_sliding()) t.qx = scene.contact->friction * pressure;
  if (!scene.shear) return t;
  const ShearSpec& spec = *scene.shear;
  if (spec.proportional) {
    (spec.along_x ? t.qx : t.qy) = spec.friction * pressure;
    return t;
  }
  if (!spec.path_x.empty())
    t.qx = io::read_grid_file(spec.path_x, scene.grid, "[shear] path_x", "value");
  if (!spec.path_y.empty())
    t.qy = io::read_grid_file(spec.path_y, scene.grid, "[shear] path_y", "value");
  return t;
}

}  // namespace coatfft::scene
