#include "cli/run_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli/npy.hpp"
#include "cli/operator_from_scene.hpp"
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

using Clock = std::chrono::steady_clock;
using coatfft::detail::seconds_since;

// Median wall time of `repeat` applications of `op` to `pressure`; leaves the result in `uz`,
// which must come out finite.
double time_applications(const Scene& scene, SurfaceOperator& op, const Field& pressure, Field& uz,
                         int repeat) {
  const double seconds = coatfft::detail::time_applications(op, pressure, uz, repeat);
  // Finite inputs can still overflow: |u| ~ p L / E* and the transforms sum p over the grid.
  COATFFT_REQUIRE(uz.allFinite(), "the displacement overflows double precision: max pressure ",
                  pressure.abs().maxCoeff(),
                  " Pa, [substrate] E* = ", scene.body.substrate().plane_strain_modulus(),
                  " Pa, [grid] lx = ", scene.grid.lx(), " m, ly = ", scene.grid.ly(),
                  " m; rescale the units of the load and the moduli");
  return seconds;
}

// Index of the cell centre nearest the origin; for an even count the two middle cells tie and
// the lower index (centre at -d/2) is taken.
Eigen::Index centre_index(std::ptrdiff_t n) {
  return static_cast<Eigen::Index>((n - 1) / 2);
}

nlohmann::json common_summary(const Scene& scene, const BuiltOperator& built, double apply_seconds,
                              int repeat, const Field& pressure, const Field& uz) {
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
  summary["uz_center"] = uz(centre_index(grid.nx()), centre_index(grid.ny()));
  summary["uz_max"] = uz.maxCoeff();
  summary["estimated_memory_bytes"] = estimate_memory(scene).bytes;
  // The contact solver's notes join this list later; they reach stderr through the exit status.
  summary["warnings"] = operator_warnings(built.report);
  for (const auto& warning : summary["warnings"])
    std::cerr << "coatfft: warning: " << warning.get<std::string>() << '\n';
  summary.update(operator_report_json(built.report));
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

void write_outputs(StagedOutput& out, const Grid& grid, const Field& pressure, const Field& uz,
                   const Field* gap, const nlohmann::json& summary) {
  write_npy(out.path("uz.npy"), uz);
  write_npy(out.path("pressure.npy"), pressure);
  if (gap) write_npy(out.path("gap.npy"), *gap);
  write_displacement_csv(out.path("displacement.csv"), grid, pressure, uz);
  {
    std::ofstream json(out.path("summary.json"));
    json << std::setw(2) << summary << '\n';
    COATFFT_REQUIRE(json.good(), "failed writing summary.json");
  }
  out.commit();
}

RunStatus run_pressure(const Scene& scene, const RunOptions& options, StagedOutput& out) {
  const Grid& grid = scene.grid;
  const Field pressure = scene_pressure(scene);
  BuiltOperator built = operator_from_scene(scene);
  Field uz;
  const double apply_seconds = time_applications(scene, *built.op, pressure, uz, options.repeat);

  nlohmann::json summary =
      common_summary(scene, built, apply_seconds, options.repeat, pressure, uz);
  const PressureSpec& load = *scene.pressure;
  if (load.kind == PressureKind::hertz && scene.body.is_homogeneous()) {
    summary["max_error_vs_hertz"] = max_error_vs_hertz(
        grid, uz, load.amplitude, load.radius, scene.body.substrate().plane_strain_modulus());
  }
  write_outputs(out, grid, pressure, uz, nullptr, summary);
  return RunStatus::ok;
}

RunStatus run_contact(Scene scene, const RunOptions& options, StagedOutput& out) {
  const ContactSpec& spec = *scene.contact;
  const Grid& grid = scene.grid;
  if (spec.indenter_material) {
    // Two homogeneous elastic bodies in frictionless normal contact deform as one half-space of
    // the composite modulus (Johnson section 4.2); only E* enters the normal compliance.
    const Material& body = scene.body.substrate();
    const double E_star = composite_modulus(body, *spec.indenter_material);
    const double nu = body.poisson_ratio();
    scene.body = LayerStack(Material(E_star * (1 - nu * nu), nu));
  }
  const Field height_field = height(grid, spec.indenter);
  BuiltOperator built = operator_from_scene(scene);

  ContactOptions contact_options;
  contact_options.tolerance = spec.tolerance;
  contact_options.max_iterations = spec.max_iterations;
  // Under load control the approach is the only output that depends on g(0) (docs/contact.md).
  contact_options.compute_approach = spec.report_approach;
  ContactSolver solver(*built.op, contact_options);
  const auto start = Clock::now();
  const ContactResult result = spec.load ? solver.solve_load(height_field, *spec.load)
                                         : solver.solve_approach(height_field, *spec.approach);
  const double solve_seconds = seconds_since(start);
  COATFFT_REQUIRE(!result.touches_boundary,
                  "[contact] the contact reaches the domain edge (pressure > 0 on a border cell): "
                  "the domain is too small for this contact; enlarge [grid] lx and ly (and nx, ny "
                  "to keep the cell size) or lower the load");

  Field uz;
  const double apply_seconds =
      time_applications(scene, *built.op, result.pressure, uz, options.repeat);
  nlohmann::json summary = common_summary(scene, built, apply_seconds, options.repeat,
                                          result.pressure, result.displacement);
  summary["indenter"] = spec.indenter_name;
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
  if (hertzian && scene.body.is_homogeneous()) {
    const double R = std::holds_alternative<Sphere>(spec.indenter)
                         ? std::get<Sphere>(spec.indenter).radius
                         : std::get<Paraboloid>(spec.indenter).radius;
    const double E_star = scene.body.substrate().plane_strain_modulus();
    const HertzSphere hertz = spec.load ? hertz_sphere_for_load(*spec.load, R, E_star)
                                        : hertz_sphere_for_approach(*spec.approach, R, E_star);
    summary["hertz"] = {{"load", hertz.load},
                        {"contact_radius", hertz.contact_radius},
                        {"max_pressure", hertz.max_pressure},
                        {"approach", hertz.approach}};
  }
  write_outputs(out, grid, result.pressure, result.displacement, &result.gap, summary);
  return result.converged ? RunStatus::ok : RunStatus::not_converged;
}

}  // namespace

RunStatus run_command(const RunOptions& options) {
  COATFFT_REQUIRE(options.repeat >= 1 && options.repeat <= max_repeat,
                  "--repeat = ", options.repeat, " must be in 1..", max_repeat);
  Scene scene = read_scene(options.scene);
  check_memory(scene, options.max_memory);
  // Every output target is checked now, before any work: a run that cannot write is refused at
  // once, not after minutes of computing.
  std::vector<std::string> names{"uz.npy", "pressure.npy", "displacement.csv", "summary.json"};
  if (scene.contact) names.push_back("gap.npy");
  StagedOutput out(options.outdir, names, scene.input_files);
  load_wisdom(scene, out);
  if (scene.contact) return run_contact(std::move(scene), options, out);
  return run_pressure(scene, options, out);
}

}  // namespace coatfft::cli
