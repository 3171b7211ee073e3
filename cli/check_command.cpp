#include "cli/check_command.hpp"

#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "convolution/operators/pipeline_error.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"
#include "frf/tabulated_frf.hpp"
#include "scene/automatic_method.hpp"
#include "scene/load_error_report.hpp"
#include "scene/operator_from_scene.hpp"
#include "scene/resources.hpp"
#include "scene/scene.hpp"
#include "scene/scene_pressure.hpp"
#include "scene/scene_run.hpp"

namespace coatfft::cli {

namespace {

// What make_operator will report as predicted_error, without building the operator.
std::optional<double> predicted_error(const scene::Scene& scene) {
  const OperatorOptions& o = scene.method.options;
  if (o.method != Method::frf_spectral && o.method != Method::frf_dcfft) return std::nullopt;
  return predicted_pipeline_error(scene.grid, *scene::body_frf(scene), o.method, o.alpha,
                                  o.threads);
}

}  // namespace

void check_command(const CheckOptions& options) {
  // run's preparation itself: the scene read, its memory checked before and after name = "auto"
  // chooses, for the applications run makes (a pressure applied once, run --repeat aside).
  scene::SceneRunOptions run;
  run.max_memory = options.max_memory;
  scene::PreparedScene prepared = scene::prepare_scene(options.scene, run);
  scene::Scene& scene = prepared.scene;
  const std::optional<AutomaticChoice>& automatic = prepared.automatic;
  const double applications = scene::expected_applications(scene, run.repeat);
  if (scene.pressure) {  // reads and checks the loads as run does
    const Field pressure = scene::scene_pressure(scene);
    scene::scene_tractions(scene, pressure);
  }
  OperatorReport report;
  report.method = scene.method.options.method;
  report.predicted_error = predicted_error(scene);
  if (report.predicted_error) report.alpha = scene.method.options.alpha;
  refuse_untrustworthy(report, "[method] name");

  const Grid& grid = scene.grid;
  const MemoryNeed memory = scene::estimate_memory(scene);
  const std::optional<double> available = available_memory();
  nlohmann::json out;
  out["scene"] = options.scene.string();
  out["problem"] = scene.contact ? "contact" : "pressure";
  out["method"] = to_string(report.method);
  out["nx"] = grid.nx();
  out["ny"] = grid.ny();
  out["lx"] = grid.lx();
  out["ly"] = grid.ly();
  out["dx"] = grid.dx();
  out["dy"] = grid.dy();
  out["method_requested"] =
      automatic || scene.method.auto_periodic ? "auto" : std::string(to_string(report.method));
  out["boundary"] = to_string(scene.boundary);
  if (automatic) out["auto"] = scene::automatic_choice_json(*automatic, scene.method.tolerance);
  const MethodCandidate cost =
      automatic ? automatic->method.chosen : scene::predicted_scene_cost(scene, applications);
  out["estimated_seconds"] = {{"setup", cost.setup_seconds},
                              {"apply", cost.apply_seconds},
                              {"applications", applications},
                              {"total", cost.total_seconds}};
  out["refinement"] = scene::refinement_json(scene);
  out["estimated_memory_bytes"] = memory.bytes;
  out["memory_drivers"] = memory.drivers;
  out["available_memory_bytes"] = available ? nlohmann::json(*available) : nlohmann::json();
  if (report.predicted_error) out["predicted_error"] = *report.predicted_error;
  if (automatic) out["predicted_error"] = out["auto"]["predicted_error"];
  out["warnings"] = operator_warnings(report);
  if (const auto* table = dynamic_cast<const TabulatedFrf*>(scene.frf.get()))
    for (const std::string& warning : table->warnings())
      out["warnings"].push_back("[frf] " + warning);
  std::cout << std::setw(2) << out << '\n';
}

}  // namespace coatfft::cli
