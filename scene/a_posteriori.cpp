#include "scene/a_posteriori.hpp"

#include <cmath>

#include "core/detail/brief.hpp"
#include "core/error.hpp"
#include "model/body_reduction.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft::scene {

namespace {

// The Hankel reference takes about 10 (a + r) / h_top quadrature panels, each FRF evaluation
// costing about in proportion to the coatings: beyond reduce_body's own limit of that work
// (model/body_reduction.hpp) the coating is far thinner than the load and the reference is not
// started. Empty where it is affordable.
std::string unaffordable_reference(const Scene& scene, double a, double r) {
  if (scene.frf || !scene.body || scene.body->is_homogeneous()) return {};
  const LayerStack& body = *scene.body;
  const double h_top = body.coatings().front().thickness;
  const double work = static_cast<double>(body.coatings().size()) * (a + r) / h_top;
  if (work <= accurate_work_limit) return {};
  return detail::concat("none: the top coating (", h_top, " m) is far thinner than the load (", a,
                        " m): the Hankel reference would take about ",
                        detail::brief(10 * (a + r) / h_top), " quadrature panels");
}

// Only the closed-form axisymmetric loads have a reference.
bool has_reference(const Scene& scene) {
  return scene.pressure && scene.pressure->kind != PressureKind::file;
}

}  // namespace

nlohmann::json a_posteriori_check(const Scene& scene, const Field& uz) {
  // Without a reference the field is not read: a distributed contact's is a rank's rows, none on
  // a rank without rows.
  if (!has_reference(scene)) return a_posteriori_check(scene, 0.0, 0.0);
  return a_posteriori_check(scene, uz(scene.grid.centre_i(), scene.grid.centre_j()),
                            uz.abs().maxCoeff());
}

nlohmann::json a_posteriori_check(const Scene& scene, double uz_at_centre, double max_abs_uz) {
  if (!has_reference(scene))
    return {{"error", nullptr},
            {"measure", "none: only hertz and uniform_disk loads have a reference"}};
  const PressureSpec& load = *scene.pressure;
  const Grid& grid = scene.grid;
  // The cell centre nearest the origin, the load's centre.
  const std::ptrdiff_t i = grid.centre_i();
  const std::ptrdiff_t j = grid.centre_j();
  const double r = std::hypot(grid.x(i), grid.y(j));
  const std::string skipped = unaffordable_reference(scene, load.radius, r);
  if (!skipped.empty()) return {{"error", nullptr}, {"measure", skipped}};
  double reference = 0.0;
  try {
    reference = hankel_displacement(*body_frf(scene), axisymmetric_shape(load), load.amplitude,
                                    load.radius, r, 1e-10);
  } catch (const Error& e) {
    // A check, not the result: a reference that does not converge is reported, not fatal.
    return {{"error", nullptr},
            {"measure", std::string("none: the Hankel reference did not converge: ") + e.what()}};
  }
  return {{"error", std::abs(uz_at_centre - reference) / max_abs_uz},
          {"measure",
           "|u - u_hankel| / max |u| at the cell nearest the load's centre: the continuous load "
           "on the scene's own body (operator, reduced body and load discretisation together)"}};
}

}  // namespace coatfft::scene
