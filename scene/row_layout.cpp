#include "scene/row_layout.hpp"

#include <limits>

#include "loads/discretization_error.hpp"
#include "scene/a_posteriori.hpp"
#include "scene/load_error_report.hpp"

namespace coatfft::scene {

namespace {

// The load's discretisation estimate of the held rows, its displacement's maximum over the holders.
nlohmann::json load_discretization(const Scene& scene, const RowLayout& rows, SurfaceOperator& op,
                                   const Field& pressure, double max_abs_uz) {
  const PressureSpec& load = *scene.pressure;
  if (load.kind == PressureKind::file) return nullptr;
  const LoadDifference d =
      load_discretization_difference(scene.grid, analytic_load(load), pressure, rows.y0);
  const Field u = op.apply(d.difference);
  return load_discretization_json(
      load,
      load_discretization_estimate(d, rows.max(u.size() ? u.abs().maxCoeff() : 0.0), max_abs_uz));
}

}  // namespace

FieldNumbers field_numbers(const Grid& grid, const RowLayout& rows, const Field& pressure,
                           const Field& uz) {
  const std::ptrdiff_t j = grid.centre_j() - rows.y0;
  const bool centre = j >= 0 && j < uz.cols();
  const double held_max = uz.size() ? uz.maxCoeff() : -std::numeric_limits<double>::infinity();
  return {rows.sum(pressure.sum()) * grid.dx() * grid.dy(),
          rows.sum(centre ? uz(grid.centre_i(), j) : 0.0), rows.max(held_max)};
}

void add_known_load_reports(nlohmann::json& summary, const Scene& scene, const RowLayout& rows,
                            const FieldNumbers& numbers, SurfaceOperator& op, const Field& pressure,
                            const Field& uz) {
  const double max_abs_uz = rows.max(uz.size() ? uz.abs().maxCoeff() : 0.0);
  // The a-posteriori check compares with the free surface's Hankel reference.
  summary["a_posteriori"] = scene.periodic()
                                ? nlohmann::json()
                                : a_posteriori_check(scene, numbers.uz_center, max_abs_uz);
  summary["load_discretization"] = load_discretization(scene, rows, op, pressure, max_abs_uz);
  summary["refinement"] = refinement_json(scene);
  if (reports_hertz_error(scene))  // 0 from a holder without rows
    summary["max_error_vs_hertz"] = rows.max(hertz_error_rows(scene, uz, rows.y0));
}

}  // namespace coatfft::scene
