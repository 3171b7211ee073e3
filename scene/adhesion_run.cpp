#include "scene/adhesion_run.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <variant>

#include "core/error.hpp"

namespace coatfft::scene {

namespace {

// Maugis' lambda = 2 sigma0 (R / (pi w K^2))^(1/3), K = 4 E*/3 of the surface's material.
double maugis_lambda(const AdhesionOptions& law, double radius, double modulus) {
  const double k = 4.0 * modulus / 3.0;
  return 2.0 * law.strength() *
         std::cbrt(radius / (std::numbers::pi * law.work_of_adhesion * k * k));
}

}  // namespace

std::vector<AdhesiveResult> solve_scene_adhesion(ContactSolver& solver, const Scene& scene,
                                                 const Field& height, ProgressObserver& progress) {
  const ContactSpec& spec = *scene.contact;
  const ContactControl control = spec.load ? ContactControl::load : ContactControl::approach;
  const std::vector<double> values =
      spec.sweep.empty() ? std::vector<double>{spec.load ? *spec.load : *spec.approach}
                         : spec.solved_values();
  const char* key = spec.load ? "load" : "approach";
  std::vector<AdhesiveResult> results;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (values.size() > 1)
      progress.step(detail::concat(key, " ", k + 1, " of ", values.size(), ": ", values[k],
                                   spec.load ? " N" : " m"));
    const AdhesiveResult* previous = results.empty() ? nullptr : &results.back();
    AdhesiveResult r = solve_adhesive(solver, height, control, values[k], *spec.adhesion, previous);
    COATFFT_REQUIRE(
        control == ContactControl::approach || r.warning.find("past pull-off") == std::string::npos,
        "[contact] load = ", values[k],
        " N is more tensile than the adhesive contact holds (past pull-off): a load "
        "cannot follow it there; give approaches instead");
    results.push_back(std::move(r));
  }
  return results;
}

nlohmann::json report_adhesion(const std::vector<AdhesiveResult>& results, const Scene& scene) {
  const ContactSpec& spec = *scene.contact;
  const AdhesionOptions& law = *spec.adhesion;
  nlohmann::json report = {{"model", "dugdale"},
                           {"work_of_adhesion", law.work_of_adhesion},
                           {"adhesion_range", law.range},
                           {"cohesive_stress", law.strength()}};
  const AdhesiveResult* pull_off = &results.front();
  int rounds = 0;
  nlohmann::json jumped = nullptr;
  for (const AdhesiveResult& r : results) {
    if (r.contact.load < pull_off->contact.load) pull_off = &r;
    rounds += r.rounds;
    if (r.jumped_off && jumped.is_null())
      jumped = r.contact.approach ? nlohmann::json(*r.contact.approach) : nlohmann::json();
  }
  report["pull_off_load"] = pull_off->contact.load;
  report["pull_off_approach"] =
      pull_off->contact.approach ? nlohmann::json(*pull_off->contact.approach) : nlohmann::json();
  report["contact_area"] = results.back().contact_area;
  report["cohesive_area"] = results.back().cohesive_area;
  report["rounds"] = rounds;
  report["jumped_off_at"] = jumped;
  report["lambda"] = nullptr;
  const std::optional<double> radius = ball_radius(spec.indenter);
  if (radius && scene.body) {
    const LayerStack& body = *scene.body;
    const Material& surface =
        body.coatings().empty() ? body.substrate() : body.coatings().front().material;
    report["lambda"] = maugis_lambda(law, *radius, surface.plane_strain_modulus());
  }
  return report;
}

}  // namespace coatfft::scene
