#include "scene/scene_pressure.hpp"

#include <cmath>

#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/load_limits.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "scene/csv.hpp"
#include "scene/npy.hpp"

namespace coatfft::scene {

namespace {

Field read_load_file(const std::filesystem::path& file, const Grid& grid, const char* key) {
  const std::string ext = file.extension().string();
  COATFFT_REQUIRE(ext == ".npy" || ext == ".csv", key, " = ", file.string(),
                  ": must end in .npy or .csv");
  Field p = ext == ".npy" ? read_npy(file) : read_csv_matrix(file);
  COATFFT_REQUIRE(p.rows() == grid.nx() && p.cols() == grid.ny(), file.string(), ": shape (",
                  p.cols(), ", ", p.rows(), ") but the grid needs (ny, nx) = (", grid.ny(), ", ",
                  grid.nx(), ")");
  for (Eigen::Index j = 0; j < p.cols(); ++j)
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      COATFFT_REQUIRE(std::isfinite(p(i, j)), file.string(), ": row ", j, ", column ", i,
                      ": value ", p(i, j), " is not finite");
  return p;
}

Field pressure_from_scene(const Scene& scene) {
  const PressureSpec& spec = *scene.pressure;
  switch (spec.kind) {
    case PressureKind::file:
      return read_load_file(spec.file, scene.grid, "[pressure] path");
    case PressureKind::hertz:
      return hertz_pressure(scene.grid, spec.amplitude, spec.radius, spec.sampling);
    case PressureKind::uniform_disk:
      return uniform_disk_pressure(scene.grid, spec.amplitude, spec.radius, spec.sampling);
  }
  throw InvalidArgument("[pressure] kind: unknown");
}

// The disk's limits on the scene's final grid (loads/load_limits.hpp), and a pressure that is not
// zero everywhere.
void require_load(const Scene& scene, const Field& pressure) {
  const PressureSpec& load = *scene.pressure;
  if (load.kind != PressureKind::file)
    require_disk_load(scene.grid, load.amplitude, load.radius, load.sampling,
                      {load.kind == PressureKind::hertz ? "[pressure] p0" : "[pressure] p",
                       "[pressure] a", "[grid] lx, ly, nx, ny"});
  COATFFT_REQUIRE((pressure != 0.0).any(),
                  load.kind == PressureKind::file ? load.file.string() : std::string("[pressure]"),
                  ": the pressure is zero on every cell: nothing to compute");
}

}  // namespace

Field scene_pressure(const Scene& scene) {
  Field pressure = pressure_from_scene(scene);
  require_load(scene, pressure);
  return pressure;
}

Tractions scene_tractions(const Scene& scene, const Field& pressure) {
  Tractions t;
  if (scene.contact && scene.contact->friction > 0.0) t.qx = scene.contact->friction * pressure;
  if (!scene.shear) return t;
  const ShearSpec& spec = *scene.shear;
  if (spec.proportional) {
    (spec.along_x ? t.qx : t.qy) = spec.friction * pressure;
    return t;
  }
  if (!spec.path_x.empty()) t.qx = read_load_file(spec.path_x, scene.grid, "[shear] path_x");
  if (!spec.path_y.empty()) t.qy = read_load_file(spec.path_y, scene.grid, "[shear] path_y");
  return t;
}

}  // namespace coatfft::scene
