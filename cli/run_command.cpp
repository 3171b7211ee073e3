#include "cli/run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli/a_posteriori.hpp"
#include "cli/automatic_method.hpp"
#include "cli/frf_table_file.hpp"
#include "cli/load_error_report.hpp"
#include "cli/npy.hpp"
#include "cli/operator_from_scene.hpp"
#include "cli/progress.hpp"
#include "cli/resources.hpp"
#include "cli/scene.hpp"
#include "cli/scene_pressure.hpp"
#include "cli/staged_output.hpp"
#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "validation/hertz.hpp"
#include "validation/hertz_contact.hpp"

namespace coatfft::cli {

namespace {

using Automatic = std::optional<AutomaticChoice>;
using Clock = std::chrono::steady_clock;
using coatfft::detail::seconds_since;

// Median wall time of `repeat` applications of `op` to `pressure`; leaves the result in `uz`,
// which must come out finite.
double time_applications(const Scene& scene, SurfaceOperator& op, const Field& pressure, Field& uz,
                         int repeat) {
  const double seconds = coatfft::detail::time_applications(op, pressure, uz, repeat);
  // Finite inputs can still overflow: |u| ~ p L / E* and the transforms sum p over the grid.
  COATFFT_REQUIRE(uz.allFinite(), "the displacement overflows double precision: max pressure ",
                  pressure.abs().maxCoeff(), " Pa, ", scene.frf ? "[frf] 2/c0" : "[substrate] E*",
                  " = ", 2.0 / body_frf(scene)->c0(), " Pa, [grid] lx = ", scene.grid.lx(),
                  " m, ly = ", scene.grid.ly(), " m; rescale the units of the load and the moduli");
  return seconds;
}

nlohmann::json common_summary(const Scene& scene, const Automatic& automatic,
                              const BuiltOperator& built, double apply_seconds, int repeat,
                              const Field& pressure, const Field& uz) {
  const Grid& grid = scene.grid;
  nlohmann::json summary;
  summary["method"] = to_string(built.report.method);
  summary["nx"] = grid.nx();
  summary["ny"] = grid.ny();
  summary["lx"] = grid.lx();
  summary["ly"] = grid.ly();
  summary["setup_seconds"] = built.report.setup_seconds;
  summary["apply_seconds"] = apply_seconds;
  summary["repeat"] = repeat;
  summary["total_load"] = pressure.sum() * grid.dx() * grid.dy();
  summary["uz_center"] = uz(grid.centre_i(), grid.centre_j());
  summary["uz_max"] = uz.maxCoeff();
  summary["estimated_memory_bytes"] = estimate_memory(scene).bytes;
  // The contact solver's notes join this list later; they reach stderr through the exit status.
  summary["warnings"] = operator_warnings(built.report);
  for (const auto& warning : summary["warnings"])
    std::cerr << "coatfft: warning: " << warning.get<std::string>() << '\n';
  summary.update(operator_report_json(built.report));
  summary["method_requested"] =
      automatic ? "auto" : std::string(to_string(scene.method.options.method));
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

// The error measure of Spinu (2021), section 5: max |u_num - u_exact| / u_exact(0).
double max_error_vs_hertz(const Grid& grid, const Field& uz, double p0, double a, double E_star) {
  const double u0 = hertz_displacement(0.0, p0, a, E_star);
  return (uz - hertz_displacement_field(grid, p0, a, E_star)).abs().maxCoeff() / u0;
}

void write_displacement_csv(const std::filesystem::path& path, const Grid& grid, const Field& p,
                            const Field& uz) {
  std::ofstream out(path);
  COATFFT_REQUIRE(out.good(), "cannot open ", path.string(), " for writing");
  out << "x,y,pressure,uz\n" << std::setprecision(17);
  for (Eigen::Index j = 0; j < grid.ny(); ++j)
    for (Eigen::Index i = 0; i < grid.nx(); ++i)
      out << grid.x(i) << ',' << grid.y(j) << ',' << p(i, j) << ',' << uz(i, j) << '\n';
  COATFFT_REQUIRE(out.good(), "failed writing ", path.string());
}

// The files a run writes, in the order of the manifest (cli/staged_output.hpp). Only these are
// checked, staged and committed.
std::vector<std::string> output_names(const OutputSpec& spec) {
  std::vector<std::string> names;
  if (spec.uz) names.push_back("uz.npy");
  if (spec.pressure) names.push_back("pressure.npy");
  if (spec.displacement_csv) names.push_back("displacement.csv");
  names.push_back("summary.json");
  if (spec.gap) names.push_back("gap.npy");
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// Writes the requested outputs only: the CSV text, the costliest of them (a 2048^2 grid makes
// hundreds of megabytes of decimal text), is not even formatted when it is not asked for.
void write_outputs(StagedOutput& out, const OutputSpec& spec, const Grid& grid,
                   const Field& pressure, const Field& uz, const Field* gap,
                   const nlohmann::json& summary, Progress& progress) {
  progress.stage("writing " + joined(output_names(spec)));
  if (spec.uz) write_npy(out.path("uz.npy"), uz);
  if (spec.pressure) write_npy(out.path("pressure.npy"), pressure);
  if (spec.gap && gap) write_npy(out.path("gap.npy"), *gap);
  if (spec.displacement_csv)
    write_displacement_csv(out.path("displacement.csv"), grid, pressure, uz);
  {
    std::ofstream json(out.path("summary.json"));
    json << std::setw(2) << summary << '\n';
    COATFFT_REQUIRE(json.good(), "failed writing summary.json");
  }
  out.commit();
}

// "setting up the operator (dcfft)".
std::string setup_stage(const Scene& scene) {
  return detail::concat("setting up the operator (", to_string(scene.method.options.method), ")");
}

std::string applications_stage(int repeat) {
  return detail::concat("applying the operator (", repeat, repeat == 1 ? " time)" : " times)");
}

RunStatus run_pressure(const Scene& scene, const Automatic& automatic, const RunOptions& options,
                       StagedOutput& out, Progress& progress) {
  const Grid& grid = scene.grid;
  const Field pressure = scene_pressure(scene);
  progress.stage(setup_stage(scene));
  BuiltOperator built = operator_from_scene(scene);
  progress.stage(applications_stage(options.repeat));
  Field uz;
  const double apply_seconds = time_applications(scene, *built.op, pressure, uz, options.repeat);

  nlohmann::json summary =
      common_summary(scene, automatic, built, apply_seconds, options.repeat, pressure, uz);
  summary["a_posteriori"] = a_posteriori_check(scene, uz);
  summary["load_discretization"] = load_discretization_json(scene, *built.op, pressure, uz);
  summary["refinement"] = refinement_json(scene);
  const PressureSpec& load = *scene.pressure;
  if (load.kind == PressureKind::hertz && !scene.frf && scene.body->is_homogeneous()) {
    summary["max_error_vs_hertz"] = max_error_vs_hertz(
        grid, uz, load.amplitude, load.radius, scene.body->substrate().plane_strain_modulus());
  }
  write_outputs(out, scene.output, grid, pressure, uz, nullptr, summary, progress);
  return RunStatus::ok;
}

ContactOptions solver_options(const ContactSpec& spec, Progress& progress) {
  ContactOptions options;
  options.tolerance = spec.tolerance;
  options.max_iterations = spec.max_iterations;
  // Under load control the approach is the only output that depends on g(0) (docs/contact.md).
  options.compute_approach = spec.report_approach;
  options.on_iteration = [&progress](int k, double residual) { progress.iteration(k, residual); };
  return options;
}

RunStatus run_contact(Scene scene, const Automatic& automatic, const RunOptions& options,
                      StagedOutput& out, Progress& progress) {
  const ContactSpec& spec = *scene.contact;
  const Grid& grid = scene.grid;
  if (spec.indenter_material) {
    // Two homogeneous elastic bodies in frictionless normal contact deform as one half-space of
    // the composite modulus (Johnson section 4.2); only E* enters the normal compliance.
    const Material& body = scene.body->substrate();
    const double E_star = composite_modulus(body, *spec.indenter_material);
    const double nu = body.poisson_ratio();
    scene.body = LayerStack(Material(E_star * (1 - nu * nu), nu));
  }
  const Field height_field = height(grid, spec.indenter);
  progress.stage(setup_stage(scene));
  BuiltOperator built = operator_from_scene(scene);

  ContactSolver solver(*built.op, solver_options(spec, progress));
  progress.stage(spec.load ? "solving the contact (load control)"
                           : "solving the contact (approach control)");
  const auto start = Clock::now();
  const ContactResult result = spec.load ? solver.solve_load(height_field, *spec.load)
                                         : solver.solve_approach(height_field, *spec.approach);
  const double solve_seconds = seconds_since(start);
  COATFFT_REQUIRE(!result.touches_boundary,
                  "[contact] the contact reaches the domain edge (pressure > 0 on a border cell): "
                  "the domain is too small for this contact; enlarge [grid] lx and ly (and nx, ny "
                  "to keep the cell size) or lower the load");

  progress.stage(applications_stage(options.repeat));
  Field uz;  // only for the timing: the solver returned the displacement
  const double apply_seconds =
      time_applications(scene, *built.op, result.pressure, uz, options.repeat);
  nlohmann::json summary = common_summary(scene, automatic, built, apply_seconds, options.repeat,
                                          result.pressure, result.displacement);
  summary["indenter"] = spec.indenter_name;
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
  summary["residual"] = result.residual;
  summary["converged"] = result.converged;
  summary["status"] = to_string(result.status);
  if (!result.warning.empty()) {
    summary["warning"] = result.warning;
    summary["warnings"].push_back(result.warning);
  }

  const bool hertzian = std::holds_alternative<Paraboloid>(spec.indenter) ||
                        std::holds_alternative<Sphere>(spec.indenter);
  if (hertzian && !scene.frf && scene.body->is_homogeneous()) {
    const double R = std::holds_alternative<Sphere>(spec.indenter)
                         ? std::get<Sphere>(spec.indenter).radius
                         : std::get<Paraboloid>(spec.indenter).radius;
    const double E_star = scene.body->substrate().plane_strain_modulus();
    const HertzSphere hertz = spec.load ? hertz_sphere_for_load(*spec.load, R, E_star)
                                        : hertz_sphere_for_approach(*spec.approach, R, E_star);
    summary["hertz"] = {{"load", hertz.load},
                        {"contact_radius", hertz.contact_radius},
                        {"max_pressure", hertz.max_pressure},
                        {"approach", hertz.approach}};
  }
  // The solver computes the gap in any case; it is saved only when [output] asks for it.
  write_outputs(out, scene.output, grid, result.pressure, result.displacement, &result.gap, summary,
                progress);
  return result.converged ? RunStatus::ok : RunStatus::not_converged;
}

}  // namespace

RunStatus run_command(const RunOptions& options) {
  COATFFT_REQUIRE(options.repeat >= 1 && options.repeat <= max_repeat,
                  "--repeat = ", options.repeat, " must be in 1..", max_repeat);
  Progress progress(progress_wanted(options.quiet, ::isatty(STDERR_FILENO) == 1), std::cerr);
  Scene scene = read_scene(options.scene);
  // name = "auto" chooses the body and the method first: the memory estimate is the chosen one's.
  const Automatic automatic = resolve_automatic_method(
      scene, scene.contact ? contact_applications : static_cast<double>(options.repeat));
  check_memory(scene, options.max_memory);
  // Every output target is checked now, before any work: a run that cannot write is refused at
  // once, not after minutes of computing. Outputs of an earlier run that this one does not
  // write are left to the manifest (stale ones removed at the commit).
  StagedOutput out(options.outdir, output_names(scene.output), scene.input_files);
  load_wisdom(scene, out);
  const RunStatus status = scene.contact
                               ? run_contact(std::move(scene), automatic, options, out, progress)
                               : run_pressure(scene, automatic, options, out, progress);
  progress.finish();
  return status;
}

}  // namespace coatfft::cli
