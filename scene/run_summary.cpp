#include "scene/run_summary.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "contact/plastic_report.hpp"
#include "core/error.hpp"
#include "scene/a_posteriori.hpp"
#include "scene/frf_table_file.hpp"
#include "scene/operator_from_scene.hpp"
#include "scene/resources.hpp"
#include "validation/hertz.hpp"
#include "validation/hertz_contact.hpp"

namespace coatfft::scene {

namespace {

// The body as the scene gives it: moduli [Pa], Poisson's ratios, coatings top first with their
// thickness [m] and the interface below each; for an [frf] table, its file.
nlohmann::json body_summary(const Scene& scene) {
  const auto medium = [](const Material& m) {
    return nlohmann::json{{"E", m.youngs_modulus()}, {"nu", m.poisson_ratio()}};
  };
  if (scene.frf) return {{"frf_table", scene.frf_file.string()}};
  nlohmann::json coatings = nlohmann::json::array();
  for (const Coating& c : scene.body->coatings()) {
    nlohmann::json layer = medium(c.material);
    layer["thickness"] = c.thickness;
    layer["interface_below"] = c.interface_below == Interface::bonded ? "bonded" : "frictionless";
    coatings.push_back(layer);
  }
  return {{"substrate", medium(scene.body->substrate())}, {"coatings", coatings}};
}

// Hertz's solution (Johnson 1985, section 4.2.1) of an indenter of radius R at the scene's load or
// approach on a half-space of plane-strain modulus E*.
nlohmann::json hertz_on_half_space(const ContactSpec& spec, double R, double E_star) {
  const HertzSphere hertz = spec.load ? hertz_sphere_for_load(*spec.load, R, E_star)
                                      : hertz_sphere_for_approach(*spec.approach, R, E_star);
  return {{"load", hertz.load},
          {"contact_radius", hertz.contact_radius},
          {"max_pressure", hertz.max_pressure},
          {"approach", hertz.approach}};
}

// summary.json's "hertz": the Hertz solution of a sphere or paraboloid on a homogeneous body, for
// comparison; null for any other contact.
nlohmann::json hertz_json(const Scene& scene) {
  const std::optional<double> R = ball_radius(scene.contact->indenter);
  if (!R || scene.frf || !scene.body->is_homogeneous() || scene.periodic() ||
      scene.contact->adhesion)
    return nullptr;
  return hertz_on_half_space(*scene.contact, *R, scene.body->substrate().plane_strain_modulus());
}

// summary.json's "hertz_bare": the Hertz solution of a sphere or paraboloid under one load on the
// bare substrate and, on a coated body, on the bare top coating, each a half-space. Under one
// coating the contact lies between the two: the body's compliance k H(k) runs from the
// substrate's 2/E* at wavelengths long against the coating to the coating's at short ones
// (docs/frf.md). Null for any other contact, an approach or a sweep.
nlohmann::json hertz_bare_json(const Scene& scene) {
  const ContactSpec& spec = *scene.contact;
  const std::optional<double> R = ball_radius(spec.indenter);
  if (!R || !spec.load || !spec.sweep.empty() || scene.frf || scene.periodic() || spec.adhesion)
    return nullptr;
  const LayerStack& body = *scene.body;
  nlohmann::json bare = {
      {"substrate", hertz_on_half_space(spec, *R, body.substrate().plane_strain_modulus())}};
  if (!body.coatings().empty())
    bare["top_coating"] =
        hertz_on_half_space(spec, *R, body.coatings().front().material.plane_strain_modulus());
  return bare;
}

}  // namespace

std::string setup_stage(const Scene& scene) {
  return detail::concat("setting up the operator (", to_string(scene.method.options.method), ")");
}

std::string applications_stage(int repeat) {
  return detail::concat("applying the operator (", repeat, repeat == 1 ? " time)" : " times)");
}

void check_repeat(int repeat) {
  COATFFT_REQUIRE(repeat >= 1 && repeat <= max_repeat, "--repeat = ", repeat, " must be in 1..",
                  max_repeat);
}

nlohmann::json common_summary(const Scene& scene, const std::optional<AutomaticChoice>& automatic,
                              const OperatorReport& report, double apply_seconds, int repeat,
                              const FieldNumbers& fields) {
  const Grid& grid = scene.grid;
  nlohmann::json summary;
  summary["method"] = to_string(report.method);
  summary["boundary"] = to_string(scene.boundary);
  summary["body"] = body_summary(scene);
  summary["nx"] = grid.nx();
  summary["ny"] = grid.ny();
  summary["lx"] = grid.lx();
  summary["ly"] = grid.ly();
  summary["setup_seconds"] = report.setup_seconds;
  summary["planning"] = to_string(scene.method.options.planning);
  summary["apply_seconds"] = apply_seconds;
  summary["repeat"] = repeat;
  summary["total_load"] = fields.total_load;
  summary["uz_center"] = fields.uz_center;
  summary["uz_max"] = fields.uz_max;
  summary["estimated_memory_bytes"] = estimate_memory(scene).bytes;
  // The contact solver's notes join this list later. Nothing is printed here: run_scene prints
  // nothing, and the CLI prints the operator's warnings itself (cli/run_command.cpp).
  summary["warnings"] = operator_warnings(report);
  if (const auto* table = dynamic_cast<const TabulatedFrf*>(scene.frf.get()))
    for (const std::string& warning : table->warnings())
      summary["warnings"].push_back("[frf] " + warning);
  if (!scene.method.reduction_note.empty())
    summary["warnings"].push_back("[method] auto: " + scene.method.reduction_note);
  summary.update(operator_report_json(report));
  summary["method_requested"] = automatic || scene.method.auto_periodic
                                    ? "auto"
                                    : std::string(to_string(scene.method.options.method));
  if (automatic) {
    summary["auto"] = automatic_choice_json(*automatic, scene.method.tolerance);
    // The operator's predicted error with the reduction's: a pipeline's own proxy prediction
    // (operator_report_json) is kept where it is larger.
    const double predicted = summary["auto"]["predicted_error"].get<double>();
    if (!summary.contains("predicted_error") || summary["predicted_error"].is_null() ||
        summary["predicted_error"].get<double>() < predicted)
      summary["predicted_error"] = predicted;
  }
  if (const auto* table = dynamic_cast<const TabulatedFrf*>(scene.frf.get()))
    summary["frf_table"] = frf_table_json(scene.frf_file, *table);
  return summary;
}

// The contact's keys of summary.json, after common_summary's.
nlohmann::json plastic_summary(const ContactResult& result, double hardness, const Grid& grid) {
  const PlasticReport plastic = plastic_report(result, hardness, grid);
  return {{"hardness", hardness},
          {"plastic_area", plastic.plastic_area},
          {"plastic_area_fraction", plastic.plastic_area_fraction},
          {"max_plastic_depth", plastic.max_plastic_depth},
          {"plastic_volume", plastic.plastic_volume}};
}

void add_contact_summary(nlohmann::json& summary, const Scene& scene, const ContactResult& result,
                         double solve_seconds) {
  const ContactSpec& spec = *scene.contact;
  summary["indenter"] = spec.indenter_name;
  if (!spec.topography.is_null()) summary["topography"] = spec.topography;
  summary["a_posteriori"] = a_posteriori_check(scene, result.displacement);
  summary["solve_seconds"] = solve_seconds;
  summary["load"] = result.load;
  // Keys that do not apply stay in the summary with the value null.
  const auto or_null = [](const std::optional<double>& value) {
    return value ? nlohmann::json(*value) : nlohmann::json();
  };
  summary["approach"] = or_null(result.approach);
  summary["contact_area"] = result.contact_area;
  // sqrt(A / pi) is a contact radius only for a round contact; for any other shape it is just
  // the radius of the disk of equal area.
  summary["equivalent_radius"] = or_null(result.contact_radius);
  summary["contact_radius"] =
      is_axisymmetric(spec.indenter) ? or_null(result.contact_radius) : nlohmann::json();
  summary["max_pressure"] = result.max_pressure;
  summary["iterations"] = result.iterations;
  summary["operator_applications"] = result.operator_applications;
  summary["coarse_applications"] = result.coarse_applications;
  summary["residual"] = result.residual;
  summary["converged"] = result.converged;
  summary["status"] = to_string(result.status);
  summary["max_penetration"] = result.max_penetration;
  if (spec.hardness) summary["plastic"] = plastic_summary(result, *spec.hardness, scene.grid);
  if (!result.warning.empty()) {
    summary["warning"] = result.warning;
    summary["warnings"].push_back(result.warning);
  }
  // Absent, not null, when it does not apply: summary.json has always been so.
  if (nlohmann::json hertz = hertz_json(scene); !hertz.is_null()) summary["hertz"] = hertz;
  if (nlohmann::json bare = hertz_bare_json(scene); !bare.is_null()) summary["hertz_bare"] = bare;
}

bool reports_hertz_error(const Scene& scene) {
  return scene.pressure && scene.pressure->kind == PressureKind::hertz && !scene.frf &&
         scene.body->is_homogeneous() && !scene.periodic();
}

double hertz_error_rows(const Scene& scene, const Field& uz, std::ptrdiff_t y0) {
  const Grid& grid = scene.grid;
  const PressureSpec& load = *scene.pressure;
  const double e_star = scene.body->substrate().plane_strain_modulus();
  if (uz.size() == 0) return 0.0;
  const Field exact =
      hertz_displacement_rows(grid, load.amplitude, load.radius, e_star, y0, uz.cols());
  return (uz - exact).abs().maxCoeff() /
         hertz_displacement(0.0, load.amplitude, load.radius, e_star);
}

}  // namespace coatfft::scene
