#include "scene/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "contact/plastic_report.hpp"
#include "contact/sliding_contact.hpp"
#include "convolution/fft/fftw_wisdom.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "scene/a_posteriori.hpp"
#include "scene/adhesion_run.hpp"
#include "scene/contact_options.hpp"
#include "scene/load_error_report.hpp"
#include "scene/operator_from_scene.hpp"
#include "scene/partial_slip_run.hpp"
#include "scene/resources.hpp"
#include "scene/row_layout.hpp"
#include "scene/run_summary.hpp"
#include "scene/scene_pressure.hpp"
#include "scene/scene_topography.hpp"

namespace coatfft::scene {

namespace {

namespace fs = std::filesystem;
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

SceneRun compute_pressure(const Scene& scene, const Automatic& automatic, int repeat,
                          ProgressObserver& progress) {
  const Grid& grid = scene.grid;
  Field pressure = scene_pressure(scene);
  progress.stage(setup_stage(scene));
  BuiltOperator built = operator_from_scene(scene);
  progress.stage(applications_stage(repeat));
  Field uz;
  const double apply_seconds = time_applications(scene, *built.op, pressure, uz, repeat);

  const RowLayout whole;  // every row, as a distributed run's slab is its rows
  const FieldNumbers numbers = field_numbers(grid, whole, pressure, uz);
  nlohmann::json summary =
      common_summary(scene, automatic, built.report, apply_seconds, repeat, numbers);
  add_known_load_reports(summary, scene, whole, numbers, *built.op, pressure, uz);
  return {grid,         std::move(pressure), std::move(uz),
          std::nullopt, std::move(summary),  RunStatus::ok};
}

// The surface response of the scene's body (convolution/kernels/traction_kernels.hpp), built once
// for the sliding contact's coupling and the in-plane displacements.
std::shared_ptr<CerrutiOperator> traction_operator(const Grid& grid, const LayerStack& body,
                                                   int threads, bool periodic) {
  TangentialOptions options;
  options.threads = threads;
  options.boundary = periodic ? Boundary::periodic : Boundary::free;
  return make_tangential_operator(grid, body, options).op;
}

// The in-plane surface displacements of a bonded body (the operator `op` of traction_operator), and
// the normal displacement of the tractions: added to uz in a known-load scene; in a contact, where
// the sliding solve has included it already (contact/sliding_contact.hpp), only reported (summary
// "tangential_uz": its largest value over the largest uz).
void add_in_plane(CerrutiOperator& op, const Tractions& q, SceneRun& run) {
  std::array<Field, 3> u;
  op.apply(run.pressure, q.qx ? &*q.qx : nullptr, q.qy ? &*q.qy : nullptr, u);
  run.ux = std::move(u[0]);
  run.uy = std::move(u[1]);
  if (!q.qx && !q.qy) return;
  const Field zero = Field::Zero(run.grid.nx(), run.grid.ny());
  op.apply(zero, q.qx ? &*q.qx : nullptr, q.qy ? &*q.qy : nullptr, u);
  run.summary["tangential_uz"] = u[2].abs().maxCoeff() / run.uz.abs().maxCoeff();
  if (run.gap) return;
  run.uz += u[2];
  run.summary["uz_max"] = run.uz.maxCoeff();
  run.summary["uz_center"] = run.uz(run.grid.centre_i(), run.grid.centre_j());
}

// An elastic indenter's surface response on the body's grid and boundary (none: rigid), for the
// relative response of contact/surface_response.hpp.
std::shared_ptr<CerrutiOperator> indenter_response(const CerrutiOperator& on_body,
                                                   const std::optional<Material>& indenter,
                                                   int threads) {
  if (!indenter) return nullptr;
  return traction_operator(on_body.grid(), LayerStack(*indenter), threads, on_body.periodic());
}

// The normal displacement of q_x relative to the indenter: the body's (any bonded stack,
// convolution/kernels/traction_kernels.hpp) less an elastic indenter's
// (contact/sliding_contact.hpp).
TangentialCoupling tangential_coupling(std::shared_ptr<CerrutiOperator> on_body,
                                       const std::optional<Material>& indenter, int threads) {
  auto on_indenter = indenter_response(*on_body, indenter, threads);
  return traction_coupling(std::move(on_body), std::move(on_indenter));
}

// The contact solve: frictionless, or under full sliding with the coupling iterated
// (contact/sliding_contact.hpp), reported in summary "friction_coupling".
ContactResult solve_scene_contact(ContactSolver& solver, const Scene& scene,
                                  const std::shared_ptr<CerrutiOperator>& surface,
                                  const Field& height_field, nlohmann::json& report,
                                  ProgressObserver& progress) {
  const ContactSpec& spec = *scene.contact;
  const ContactControl control = spec.load ? ContactControl::load : ContactControl::approach;
  const double value = spec.load ? *spec.load : *spec.approach;
  if (spec.friction == 0.0) return solver.solve(height_field, control, value);
  SlidingOptions options;
  options.friction = spec.friction;
  // Each solve is converged to spec.tolerance: the change between two solves cannot be smaller.
  options.tolerance = 10.0 * spec.tolerance;
  options.on_solve = [&progress, most = options.max_iterations](int k) {
    progress.step(detail::concat("friction coupling: normal solve ", k, " of at most ", most));
  };
  SlidingReport r;
  ContactResult result = solve_sliding(
      solver,
      // A scene with friction writes ux.npy and uy.npy (scene/scene.cpp): its surface response is
      // built.
      tangential_coupling(surface, spec.indenter_material, scene.method.options.threads),
      height_field, control, value, options, &r);
  report = {{"solves", r.solves},
            {"pressure_change", r.pressure_change},
            {"pressure_shift", r.pressure_shift},
            {"centroid_shift", r.centroid_shift},
            {"converged", r.converged}};
  return result;
}

// One value of a sweep: a row of sweep.csv and of summary.json's "sweep"; plastic_area is 0
// without a hardness, cohesive_area [m^2] without adhesion.
nlohmann::json sweep_row(const Grid& grid, const ContactResult& r,
                         const std::optional<double>& hardness, bool unloading,
                         double cohesive_area) {
  return {{"load", r.load},
          {"approach", r.approach ? nlohmann::json(*r.approach) : nlohmann::json()},
          {"area_fraction", r.contact_area / (grid.lx() * grid.ly())},
          {"max_pressure", r.max_pressure},
          {"mean_gap", r.gap.mean()},
          {"iterations", r.iterations},
          {"operator_applications", r.operator_applications},
          {"coarse_applications", r.coarse_applications},
          {"converged", r.converged},
          {"max_penetration", r.max_penetration},
          {"plastic_area", hardness ? plastic_report(r, *hardness, grid).plastic_area : 0.0},
          {"phase", unloading ? "unload" : "load"},
          {"cohesive_area", cohesive_area}};
}

// Whether the contact of any solve reaches the border cells of a measured topography's map;
// refuses one that reaches the pad around it ([grid] pad), which was to be out of reach.
bool topography_edge_contact(const std::vector<ContactResult>& results, std::int64_t pad) {
  bool map_edge = false;
  for (const ContactResult& r : results) {
    const PadContact c = pad_contact(r.pressure, pad);
    COATFFT_REQUIRE(!c.pad,
                    "[grid] pad: the contact reaches the pad around the topography (its "
                    "gap is out of reach only up to twice the map's largest gap): lower "
                    "the load or approach");
    map_edge = map_edge || c.map_edge;
  }
  return map_edge;
}

// The solves of a [contact] scene: its one value, or each value of its sweep (ascending).
std::vector<ContactResult> solve_contacts(ContactSolver& solver, const Scene& scene,
                                          const std::shared_ptr<CerrutiOperator>& surface,
                                          const Field& height_field, nlohmann::json& coupling,
                                          ProgressObserver& progress) {
  const ContactSpec& spec = *scene.contact;
  const ContactControl control = spec.load ? ContactControl::load : ContactControl::approach;
  try {
    if (!spec.sweep.empty())
      return solver.solve_sweep(height_field, control, spec.sweep, spec.unload);
    std::vector<ContactResult> one;
    one.push_back(solve_scene_contact(solver, scene, surface, height_field, coupling, progress));
    return one;
  } catch (const InvalidArgument& e) {
    // The solver names what it refuses as its own ("ContactSolver: load = 1e+30 N ..."): in a
    // scene that is a [contact] key and its value (one of a sweep's list).
    const std::string message = e.what();
    const std::string prefix = "ContactSolver: ";
    if (message.rfind(prefix, 0) != 0) throw;
    throw InvalidArgument(detail::concat("[contact] ", message.substr(prefix.size())));
  }
}

// The refusal of a contact that reaches the domain edge, naming the first value of a sweep whose
// contact does (the loading branch's later values are larger: solved in ascending order).
std::string domain_edge_message(const ContactSpec& spec,
                                const std::vector<ContactResult>& results) {
  if (spec.sweep.empty()) return domain_edge_refusal;
  const std::vector<double> values = spec.solved_values();
  std::size_t k = 0;
  while (k + 1 < results.size() && !results[k].touches_boundary) ++k;
  const char* key = spec.load ? "load" : "approach";
  return detail::concat(domain_edge_refusal, " (first at [contact] ", key, " = ", values[k],
                        spec.load ? " N" : " m", ", value ", k + 1, " of the sweep's ",
                        values.size(), ")");
}

// A sweep's outputs: every value's fields, stacked by the writer, and its rows; the summary's
// other contact keys are the last solve's, and it converged when every value did.
void add_sweep(SceneRun& run, std::vector<ContactResult>& results, const ContactSpec& spec,
               const std::vector<double>& cohesive_areas) {
  nlohmann::json rows = nlohmann::json::array();
  SweepFields fields;
  bool converged = true;
  for (std::size_t k = 0; k < results.size(); ++k) {
    ContactResult& r = results[k];
    rows.push_back(sweep_row(run.grid, r, spec.hardness, k >= spec.loading_steps(),
                             cohesive_areas.empty() ? 0.0 : cohesive_areas[k]));
    converged = converged && r.converged;
    fields.pressure.push_back(std::move(r.pressure));
    fields.uz.push_back(std::move(r.displacement));
    fields.gap.push_back(std::move(r.gap));
    if (spec.hardness) fields.plastic.push_back(std::move(r.plastic_depth));
  }
  run.summary["sweep"] = rows;
  run.summary["converged"] = converged;
  run.status = converged ? RunStatus::ok : RunStatus::not_converged;
  run.sweep = std::move(fields);
}

// `surface`: the body's surface response (traction_operator) when the scene writes ux.npy, for
// the friction coupling; built before an elastic indenter's composite modulus replaces the body
// for the normal compliance.
// The scene's body is replaced by the normal compliance's and a height map's heights are moved
// out (a large map is not held twice: docs/scale.md, "Memory per cell").
SceneRun compute_contact(Scene& scene, const Automatic& automatic, int repeat,
                         ProgressObserver& progress,
                         const std::shared_ptr<CerrutiOperator>& surface) {
  const ContactSpec& spec = *scene.contact;
  use_normal_compliance_body(scene);
  const Field height_field = take_height(scene.grid, scene.contact->indenter);
  progress.stage(setup_stage(scene));
  BuiltOperator built = operator_from_scene(scene);

  ContactSolver solver(*built.op, solver_options(spec, scene.method.options.threads, progress));
  progress.stage(detail::concat("solving the contact (", spec.load ? "load" : "approach",
                                " control", spec.sweep.empty() ? "" : ", a sweep", ")"));
  const auto start = Clock::now();
  nlohmann::json coupling;
  std::vector<PartialSlipResult> slip_steps;
  std::vector<ContactResult> results;
  nlohmann::json adhesion;
  std::vector<double> cohesive_areas;
  if (spec.partial_slip()) {
    // A scene with a partial slip writes ux.npy and uy.npy (scene/scene.cpp): its surface
    // response is built.
    RelativeSurfaceResponse response(
        surface, indenter_response(*surface, spec.indenter_material, scene.method.options.threads));
    slip_steps = solve_scene_partial_slip(solver, response, spec, height_field, progress);
    results.push_back(slip_steps.back().normal);
  } else if (spec.adhesion) {
    std::vector<AdhesiveResult> adhesive =
        solve_scene_adhesion(solver, scene, height_field, progress);
    adhesion = report_adhesion(adhesive, scene);
    for (AdhesiveResult& a : adhesive) {
      cohesive_areas.push_back(a.cohesive_area);
      results.push_back(std::move(a.contact));
    }
  } else {
    results = solve_contacts(solver, scene, surface, height_field, coupling, progress);
  }
  const double solve_seconds = seconds_since(start);
  // touches_boundary is false on a periodic surface (no edge: contact/contact_solver.hpp).
  const bool touches = std::any_of(results.begin(), results.end(),
                                   [](const ContactResult& r) { return r.touches_boundary; });
  // A measured topography on a free boundary is the whole surface there is: beyond the map the
  // gap is out of reach, so contact on its edge cells is the map's own (reported, not refused).
  const bool topography = !spec.topography.is_null();
  const bool map_edge = topography && topography_edge_contact(results, spec.topography_pad);
  COATFFT_REQUIRE(!touches || topography, domain_edge_message(spec, results));
  // The last solve's (the largest value's, or the last unloading step's): the summary's contact
  // keys (a sweep keeps every value's fields too).
  ContactResult result = spec.sweep.empty() ? std::move(results.back()) : results.back();

  progress.stage(applications_stage(repeat));
  Field uz;  // only for the timing: the solver returned the displacement
  const double apply_seconds = time_applications(scene, *built.op, result.pressure, uz, repeat);
  nlohmann::json summary =
      common_summary(scene, automatic, built.report, apply_seconds, repeat,
                     field_numbers(scene.grid, RowLayout{}, result.pressure, result.displacement));
  add_contact_summary(summary, scene, result, solve_seconds);
  if (!coupling.is_null()) summary["friction_coupling"] = coupling;
  if (!adhesion.is_null()) summary["adhesion"] = adhesion;
  if (topography) summary["topography"]["contact_at_edge"] = map_edge;
  // The solver computes the gap in any case; the CLI saves it only when [output] asks for it.
  SceneRun run{scene.grid,
               std::move(result.pressure),
               std::move(result.displacement),
               std::move(result.gap),
               std::move(summary),
               result.converged ? RunStatus::ok : RunStatus::not_converged};
  if (spec.hardness) {
    if (spec.unload) run.residual_gap = residual_gap(height_field, result.plastic_depth);
    run.plastic = std::move(result.plastic_depth);
  }
  if (!spec.sweep.empty()) add_sweep(run, results, spec, cohesive_areas);
  if (!slip_steps.empty()) add_partial_slip(run, slip_steps, spec);
  return run;
}

// run_scene's FFTW wisdom: the scene's wisdom file is imported when it exists. Building and
// computing write no file (the program saves the wisdom itself, cli/wisdom_file.hpp), and the
// checks of load_wisdom guard only what `coatfft run` is about to write (the wisdom file must not
// be an input or an output of the run, nor a file of another kind).
// Wisdom only makes planning faster: a file that does not hold FFTW's (or another version's) is
// ignored, as a missing one is. A FIFO, a device or an oversized file is still refused before
// anything is read (io/input_file.hpp).
void import_wisdom_read_only(const Scene& scene) {
  const fs::path& wisdom = scene.method.wisdom;
  std::error_code ec;
  if (wisdom.empty() || !fs::exists(fs::status(wisdom, ec))) return;
  const std::string text = read_wisdom_file(wisdom);
  if (holds_fftw_wisdom(text)) import_fftw_wisdom(text);
}

}  // namespace

PreparedScene prepare_scene(const fs::path& scene_file, const SceneRunOptions& options) {
  check_repeat(options.repeat);
  Scene scene = read_scene(scene_file, SceneReading{.max_memory = options.max_memory});
  // name = "auto" chooses the body and the method first, and the memory estimate is the chosen
  // one's; before it, the estimate of the scene as read (DC-FFT's padded lattice, the least any
  // candidate but direct summation on a small grid needs) refuses a grid too large for any.
  check_memory(scene, options.max_memory);
  std::optional<AutomaticChoice> automatic =
      resolve_automatic_method(scene, expected_applications(scene, options.repeat));
  check_memory(scene, options.max_memory);
  return {std::move(scene), std::move(automatic)};
}

SceneRun compute_scene(PreparedScene prepared, const SceneRunOptions& options) {
  // Without an observer of the caller's, the default one, which reports nothing.
  ProgressObserver silent;
  ProgressObserver& progress = options.progress ? *options.progress : silent;
  // The stresses need the body as the scene gives it (an elastic indenter's composite modulus
  // replaces it for the contact solve only).
  const std::optional<StressSpec> stress = prepared.scene.stress;
  const std::optional<LayerStack> body = prepared.scene.body;
  const Scene& scene = prepared.scene;  // compute_contact changes its body and heights only
  const int threads = prepared.scene.method.options.threads;
  std::shared_ptr<CerrutiOperator> surface;
  if (scene.output.in_plane) {
    progress.stage("setting up the surface response to tractions");
    surface = traction_operator(scene.grid, *body, threads, scene.periodic());
  }
  SceneRun run =
      prepared.scene.contact
          ? compute_contact(prepared.scene, prepared.automatic, options.repeat, progress, surface)
          : compute_pressure(prepared.scene, prepared.automatic, options.repeat, progress);
  Tractions q = scene_tractions(scene, run.pressure);
  if (run.partial_slip) {  // the last step's tractions
    q.qx = run.partial_slip->shear_x.back();
    q.qy = run.partial_slip->shear_y.back();
  }
  if (stress) {
    progress.stage("stresses on " + std::to_string(stress_planes(*stress, *body).depths.size()) +
                   " planes");
    const OutputSpec& o = scene.output;
    const StressArrays arrays{o.stress,
                              o.von_mises,
                              o.stress_section,
                              o.von_mises_section,
                              o.stress_interfaces,
                              o.von_mises_interfaces};
    run.stress =
        compute_stress(*stress, *body, run.grid, run.pressure, q, threads, progress, arrays);
    run.summary["stress"] = run.stress->summary;
  }
  if (scene.output.in_plane) {
    progress.stage("in-plane surface displacements");
    add_in_plane(*surface, q, run);
  } else if (stress && !scene.output.listed) {
    // Only [stress] asked for them (tractions would have been refused): say why they are missing.
    run.summary["warnings"].push_back(
        body->all_bonded()
            ? "ux.npy and uy.npy are not written: the top coating is too thin against the domain "
              "for its traction kernels (convolution/kernels/traction_kernels.hpp)"
            : "ux.npy and uy.npy are not written: a body with a frictionless interface has no "
              "finite in-plane surface response (the coating slides)");
  }
  run.summary["ranks"] = 1;  // a distributed run's count (scene/distributed_run.hpp)
  return run;
}

std::vector<double> stacked_fields(const std::vector<Field>& fields) {
  std::vector<double> values;
  for (const Field& f : fields) values.insert(values.end(), f.data(), f.data() + f.size());
  return values;
}

std::string sweep_csv(const nlohmann::json& rows) {
  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);
  csv << "load,approach,area_fraction,max_pressure,mean_gap,iterations,operator_applications,"
         "converged,max_penetration,plastic_area,phase,cohesive_area\n";
  for (const nlohmann::json& r : rows) {
    csv << r["load"].get<double>() << ',';
    if (!r["approach"].is_null()) csv << r["approach"].get<double>();
    csv << ',' << r["area_fraction"].get<double>() << ',' << r["max_pressure"].get<double>() << ','
        << r["mean_gap"].get<double>() << ',' << r["iterations"].get<int>() << ','
        << r["operator_applications"].get<int>() << ',' << (r["converged"].get<bool>() ? 1 : 0)
        << ',' << r["max_penetration"].get<double>() << ',' << r["plastic_area"].get<double>()
        << ',' << r["phase"].get<std::string>() << ',' << r["cohesive_area"].get<double>() << '\n';
  }
  return csv.str();
}

SceneRun run_scene(const fs::path& scene_file, const SceneRunOptions& options) {
  PreparedScene prepared = prepare_scene(scene_file, options);
  import_wisdom_read_only(prepared.scene);
  return compute_scene(std::move(prepared), options);
}

}  // namespace coatfft::scene
