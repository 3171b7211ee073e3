#include "scene/automatic_method.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <variant>

#include "convolution/operators/make_operator.hpp"
#include "scene/method_request.hpp"
#include "validation/hertz_contact.hpp"

namespace coatfft::scene {

namespace {

// The plane-strain moduli that may set a contact's size: the substrate's and the top layer's
// (a coated contact's radius lies between the two half-spaces'); for a table body 2/c0 and
// 2/c_inf, which are the same two.
std::vector<double> bounding_moduli(const Scene& scene) {
  if (scene.frf) return {2.0 / scene.frf->c0(), 2.0 / scene.frf->c_inf()};
  const LayerStack& body = *scene.body;
  std::vector<double> moduli{body.substrate().plane_strain_modulus()};
  if (!body.is_homogeneous())
    moduli.push_back(body.coatings().front().material.plane_strain_modulus());
  return moduli;
}

std::vector<ReferenceLoad> contact_loads(const Scene& scene, const ContactSpec& spec) {
  const Grid& grid = scene.grid;
  if (const auto* punch = std::get_if<FlatPunch>(&spec.indenter))
    return {{AxisymmetricLoad::uniform_disk, punch->radius}};
  const std::optional<double> radius = ball_radius(spec.indenter);
  // An adhesive contact's size is not Hertz's (its load may be tensile, its approach negative).
  if (!radius || spec.adhesion) return unknown_load_references(grid);
  std::vector<ReferenceLoad> loads;
  for (const double E_star : bounding_moduli(scene)) {
    const HertzSphere h = spec.load ? hertz_sphere_for_load(*spec.load, *radius, E_star)
                                    : hertz_sphere_for_approach(*spec.approach, *radius, E_star);
    loads.push_back({AxisymmetricLoad::hertz, h.contact_radius});
  }
  return loads;
}

}  // namespace

std::vector<ReferenceLoad> reference_loads(const Scene& scene) {
  const Grid& grid = scene.grid;
  std::vector<ReferenceLoad> loads;
  if (scene.contact) {
    loads = contact_loads(scene, *scene.contact);
  } else if (scene.pressure->kind == PressureKind::file) {
    loads = unknown_load_references(grid);
  } else {
    loads = {{axisymmetric_shape(*scene.pressure), scene.pressure->radius}};
  }
  // A load narrower than a cell acts on the grid as one cell.
  for (ReferenceLoad& load : loads) load.radius = std::max(load.radius, grid.dx() * 0.5);
  return loads;
}

double expected_applications(const Scene& scene, int repeat) {
  return scene.contact ? contact_applications : static_cast<double>(repeat);
}

std::optional<AutomaticChoice> resolve_automatic_method(Scene& scene, double applications,
                                                        bool distributed) {
  MethodSpec& m = scene.method;
  OperatorRequest request = operator_request(m);
  AutoRequest& choice = request.automatic_request;
  choice.applications = applications;
  choice.first_in_process = true;  // a command-line run builds one operator
  choice.distributed = distributed;
  if (request.automatic) request.loads = reference_loads(scene);
  OperatorPlan plan = scene.frf ? plan_operator(scene.grid, *scene.frf, request)
                                : plan_operator(scene.grid, *scene.body, request);
  m.options = plan.options;
  if (plan.reduced_body) m.reduced_body = std::move(plan.reduced_body);
  if (!plan.reduction_note.empty()) m.reduction_note = plan.reduction_note;
  return std::move(plan.choice);
}

namespace {

nlohmann::json finite_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

nlohmann::json candidate_json(const MethodCandidate& c) {
  return {{"method", to_string(c.method)},
          {"admissible", c.admissible},
          {"predicted_error", finite_or_null(c.predicted_error)},
          {"predicted_setup_seconds", c.setup_seconds},
          {"predicted_apply_seconds", c.apply_seconds},
          {"predicted_total_seconds", c.total_seconds},
          {"note", c.note}};
}

nlohmann::json reduction_json(const BodyReduction& r) {
  nlohmann::json tried = nlohmann::json::array();
  for (const auto& [kind, effect] : r.tried) tried.push_back({{"kind", kind}, {"effect", effect}});
  return {
      {"kind", r.kind},
      {"estimated_effect", r.estimated_effect},
      {"why", r.why},
      {"tried", tried},
      {"work", {{"frf_evaluations", r.work.frf_evaluations}, {"quadratures", r.work.quadratures}}}};
}

}  // namespace

nlohmann::json automatic_choice_json(const AutomaticChoice& choice, double tolerance) {
  const MethodCandidate& c = choice.method.chosen;
  nlohmann::json out;
  out["tolerance"] = tolerance;
  out["applications"] = choice.applications;
  out["method"] = to_string(c.method);
  out["why"] = choice.method.why;
  out["threads"] = choice.method.options.threads;
  if (c.method == Method::frf_split) out["split_tolerance"] = choice.method.options.split.tolerance;
  const double effect = choice.reduction ? choice.reduction->estimated_effect : 0.0;
  out["predicted_error"] = c.predicted_error + effect;
  out["predicted_operator_error"] = c.predicted_error;
  out["predicted_setup_seconds"] = c.setup_seconds;
  out["predicted_apply_seconds"] = c.apply_seconds;
  out["predicted_total_seconds"] = c.total_seconds;
  out["candidates"] = nlohmann::json::array();
  for (const MethodCandidate& k : choice.method.candidates)
    out["candidates"].push_back(candidate_json(k));
  out["reduction"] = choice.reduction ? reduction_json(*choice.reduction) : nlohmann::json();
  out["reference_loads"] = nlohmann::json::array();
  for (const ReferenceLoad& load : choice.reference_loads)
    out["reference_loads"].push_back(
        {{"shape", load.shape == AxisymmetricLoad::hertz ? "hertz" : "uniform_disk"},
         {"radius", load.radius}});
  return out;
}

MethodCandidate predicted_scene_cost(const Scene& scene, double applications) {
  const OperatorOptions& o = scene.method.options;
  if (scene.frf) return predict_method(scene.grid, *scene.frf, o, applications, true);
  const LayerStack& body = scene.method.reduced_body ? *scene.method.reduced_body : *scene.body;
  return predict_method(scene.grid, body, o, applications, true);
}

}  // namespace coatfft::scene
