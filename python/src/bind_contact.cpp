// solve_contact and ContactResult: the Polonsky & Keer (1999) solver of contact/ on an Operator.
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "contact/adhesive_contact.hpp"
#include "contact/contact_solver.hpp"
#include "contact/plastic_report.hpp"
#include "contact/sliding_contact.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "operator.hpp"
#include "scene/run_summary.hpp"
#include "solve_setup.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

// The result with its fields as numpy arrays (moved, not copied).
struct PyContactResult {
  py::array_t<double> pressure, displacement, gap;
  double load = 0.0;
  std::optional<double> approach;
  double contact_area = 0.0;
  std::optional<double> contact_radius;
  double max_pressure = 0.0;
  int iterations = 0;
  int operator_applications = 0;
  int coarse_applications = 0;
  double residual = 0.0;
  bool converged = false;
  std::string status;
  bool touches_boundary = false;
  double max_penetration = 0.0;
  std::string warning;
  py::object friction_coupling = py::none();  // solve_sliding's report, as summary.json's
  // Under a hardness: the plastic depth and summary.json's "plastic" (plastic_report); a
  // sweep's "load" or "unload" branch.
  py::object plastic_depth = py::none(), plastic = py::none(), phase = py::none();
  // With adhesion: the cohesive zone's area [m^2] and whether the contact jumped off.
  py::object cohesive_area = py::none(), jumped_off = py::none();
};

// The Dugdale law of the keywords adhesion=, work_of_adhesion=, adhesion_range= (none without
// adhesion); `what` names the function in the messages.
std::optional<AdhesionOptions> adhesion_law(const std::optional<std::string>& adhesion,
                                            std::optional<double> work, std::optional<double> range,
                                            const char* what) {
  if (!adhesion) {
    COATFFT_REQUIRE(!work && !range, what,
                    ": work_of_adhesion and adhesion_range need adhesion=\"dugdale\"");
    return std::nullopt;
  }
  COATFFT_REQUIRE(*adhesion == "dugdale", what, ": adhesion = '", *adhesion,
                  "', but the cohesive law is \"dugdale\"");
  COATFFT_REQUIRE(work && range, what,
                  ": adhesion=\"dugdale\" needs work_of_adhesion [J/m^2] and "
                  "adhesion_range [m]");
  return AdhesionOptions{*work, *range};
}

PyContactResult to_python(ContactResult&& r, const std::optional<double>& hardness = std::nullopt,
                          const Grid* grid = nullptr) {
  PyContactResult out;
  if (hardness && grid) {
    out.plastic = dict_from_json_text(scene::plastic_summary(r, *hardness, *grid).dump());
    out.plastic_depth = array_from_field(std::move(r.plastic_depth));
  }
  out.pressure = array_from_field(std::move(r.pressure));
  out.displacement = array_from_field(std::move(r.displacement));
  out.gap = array_from_field(std::move(r.gap));
  out.load = r.load;
  out.approach = r.approach;
  out.contact_area = r.contact_area;
  out.contact_radius = r.contact_radius;
  out.max_pressure = r.max_pressure;
  out.iterations = r.iterations;
  out.operator_applications = r.operator_applications;
  out.coarse_applications = r.coarse_applications;
  out.residual = r.residual;
  out.converged = r.converged;
  out.status = std::string(to_string(r.status));
  out.touches_boundary = r.touches_boundary;
  out.max_penetration = r.max_penetration;
  out.warning = r.warning;
  return out;
}

PyContactResult to_python(AdhesiveResult&& r) {
  const double cohesive = r.cohesive_area;
  const bool jumped = r.jumped_off;
  PyContactResult out = to_python(std::move(r.contact));
  out.cohesive_area = py::float_(cohesive);
  out.jumped_off = py::bool_(jumped);
  return out;
}

PyContactResult solve_contact(Operator& op, const DoubleArray& height, std::optional<double> load,
                              std::optional<double> approach, double tolerance, int max_iterations,
                              bool preconditioned, std::optional<double> hardness,
                              const std::optional<std::string>& adhesion,
                              std::optional<double> work_of_adhesion,
                              std::optional<double> adhesion_range) {
  COATFFT_REQUIRE(load.has_value() != approach.has_value(),
                  "solve_contact: give exactly one of load [N] and approach [m]");
  const Field h = field_from_array(height, op.grid(), "solve_contact: height");
  ContactOptions options = contact_options(op, approach.has_value(), tolerance, max_iterations,
                                           preconditioned, "solve_contact");
  options.hardness = hardness;
  const std::optional<AdhesionOptions> law =
      adhesion_law(adhesion, work_of_adhesion, adhesion_range, "solve_contact");
  COATFFT_REQUIRE(!law || !hardness, "solve_contact: adhesion is not combined with hardness yet");
  if (law) {
    AdhesiveResult r = without_gil([&] {
      const auto guard = op.lock();
      ContactSolver solver(op.op(), options);
      return solve_adhesive(solver, h, load ? ContactControl::load : ContactControl::approach,
                            load ? *load : *approach, *law);
    });
    return to_python(std::move(r));
  }
  ContactResult result = without_gil([&] {
    const auto guard = op.lock();
    ContactSolver solver(op.op(), options);
    return load ? solver.solve_load(h, *load) : solver.solve_approach(h, *approach);
  });
  return to_python(std::move(result), hardness, &op.grid());
}

// Full sliding (contact/sliding_contact.hpp): the normal contact with q_x = mu p, the tractions'
// normal displacement of the bonded body `body_object` iterated into the gap, as a scene's
// [contact] friction (each solve to `tolerance`, the coupling to ten times it).
PyContactResult solve_sliding(Operator& op, const DoubleArray& height, py::handle body_object,
                              double friction, std::optional<double> load,
                              std::optional<double> approach, double tolerance, int max_iterations,
                              bool preconditioned, int threads) {
  COATFFT_REQUIRE(load.has_value() != approach.has_value(),
                  "solve_sliding: give exactly one of load [N] and approach [m]");
  COATFFT_REQUIRE(std::isfinite(friction) && friction >= 0.0 && friction <= 10.0,
                  "solve_sliding: friction = ", friction, " must be in [0, 10]");
  const LayerStack body =
      layers_of(body_object, "solve_sliding", "the tractions' response needs the layers");
  require_operator_body(op, body, "solve_sliding");
  const Field h = field_from_array(height, op.grid(), "solve_sliding: height");
  const ContactOptions options = contact_options(op, approach.has_value(), tolerance,
                                                 max_iterations, preconditioned, "solve_sliding");
  SlidingOptions sliding;
  sliding.friction = friction;
  sliding.tolerance = 10.0 * tolerance;
  SlidingReport report;
  ContactResult result = without_gil([&] {
    const auto guard = op.lock();
    ContactSolver solver(op.op(), options);
    return coatfft::solve_sliding(solver, traction_coupling(surface_response(op, body, threads)), h,
                                  load ? ContactControl::load : ContactControl::approach,
                                  load ? *load : *approach, sliding, &report);
  });
  PyContactResult out = to_python(std::move(result));
  py::dict coupling;
  coupling["solves"] = report.solves;
  coupling["pressure_change"] = report.pressure_change;
  coupling["pressure_shift"] = report.pressure_shift;
  coupling["centroid_shift"] = report.centroid_shift;
  coupling["converged"] = report.converged;
  out.friction_coupling = coupling;
  return out;
}

// solve_adhesive_path over the values in a sweep's order (ascending, then with `unload` back
// down), each result with its phase.
std::vector<PyContactResult> adhesive_sweep(Operator& op, const Field& h, ContactControl control,
                                            const std::vector<double>& values, bool unload,
                                            const ContactOptions& options,
                                            const AdhesionOptions& law) {
  const std::vector<double> order = sweep_order(values, unload);
  std::vector<AdhesiveResult> results = without_gil([&] {
    const auto guard = op.lock();
    ContactSolver solver(op.op(), options);
    return solve_adhesive_path(solver, h, control, order, law);
  });
  std::vector<PyContactResult> out;
  for (std::size_t k = 0; k < results.size(); ++k) {
    out.push_back(to_python(std::move(results[k])));
    out.back().phase = py::str(k < values.size() ? "load" : "unload");
  }
  return out;
}

// ContactSolver::solve_sweep: the results in ascending order of the values, then with `unload`
// the unloading branch.
std::vector<PyContactResult> solve_sweep(Operator& op, const DoubleArray& height,
                                         std::optional<std::vector<double>> loads,
                                         std::optional<std::vector<double>> approaches,
                                         double tolerance, int max_iterations, bool preconditioned,
                                         std::optional<double> hardness, bool unload,
                                         const std::optional<std::string>& adhesion,
                                         std::optional<double> work_of_adhesion,
                                         std::optional<double> adhesion_range) {
  COATFFT_REQUIRE(loads.has_value() != approaches.has_value(),
                  "solve_sweep: give exactly one of loads [N] and approaches [m]");
  const std::optional<AdhesionOptions> law =
      adhesion_law(adhesion, work_of_adhesion, adhesion_range, "solve_sweep");
  COATFFT_REQUIRE(!law || !hardness, "solve_sweep: adhesion is not combined with hardness yet");
  COATFFT_REQUIRE(!unload || hardness.has_value() || law.has_value(),
                  "solve_sweep: unload=True needs hardness or adhesion: the unloading of an "
                  "elastic contact repeats its loading");
  const Field h = field_from_array(height, op.grid(), "solve_sweep: height");
  ContactOptions options = contact_options(op, approaches.has_value(), tolerance, max_iterations,
                                           preconditioned, "solve_sweep");
  options.hardness = hardness;
  const std::vector<double>& values = loads ? *loads : *approaches;
  if (law)
    return adhesive_sweep(op, h, loads ? ContactControl::load : ContactControl::approach, values,
                          unload, options, *law);
  std::vector<ContactResult> results = without_gil([&] {
    const auto guard = op.lock();
    ContactSolver solver(op.op(), options);
    return solver.solve_sweep(h, loads ? ContactControl::load : ContactControl::approach, values,
                              unload);
  });
  std::vector<PyContactResult> out;
  for (std::size_t k = 0; k < results.size(); ++k) {
    out.push_back(to_python(std::move(results[k]), hardness, &op.grid()));
    out.back().phase = py::str(k < values.size() ? "load" : "unload");
  }
  return out;
}

// coatfft::residual_gap on two (ny, nx) arrays.
py::array_t<double> residual_gap_of(const DoubleArray& height, const DoubleArray& depth) {
  for (const auto& [array, what] : {std::pair{&height, "height"}, {&depth, "plastic_depth"}})
    COATFFT_REQUIRE(array->ndim() == 2, "residual_gap: ", what, " must be a 2-D array (ny, nx)");
  Field h, d;
  copy_into_field(height, h, "residual_gap: height");
  copy_into_field(depth, d, "residual_gap: plastic_depth");
  return array_from_field(residual_gap(h, d));
}

}  // namespace

void bind_contact(py::module_& m) {
  py::class_<PyContactResult>(m, "ContactResult", "One contact solve: fields (ny, nx) and scalars.")
      .def_readonly("pressure", &PyContactResult::pressure, "p [Pa]")
      .def_readonly("displacement", &PyContactResult::displacement, "u [m]")
      .def_readonly("gap", &PyContactResult::gap, "h + u - approach [m]")
      .def_readonly("load", &PyContactResult::load, "total force [N]")
      .def_readonly("approach", &PyContactResult::approach, "rigid-body approach [m]")
      .def_readonly("contact_area", &PyContactResult::contact_area, "[m^2]")
      .def_readonly("contact_radius", &PyContactResult::contact_radius,
                    "sqrt(area / pi) [m]; None without contact")
      .def_readonly("max_pressure", &PyContactResult::max_pressure, "[Pa]")
      .def_readonly("iterations", &PyContactResult::iterations)
      .def_readonly("operator_applications", &PyContactResult::operator_applications)
      .def_readonly("coarse_applications", &PyContactResult::coarse_applications,
                    "applications on the coarser grids of the nested start")
      .def_readonly("residual", &PyContactResult::residual, "last relative pressure change")
      .def_readonly("converged", &PyContactResult::converged)
      .def_readonly("status", &PyContactResult::status,
                    "\"converged\", \"iteration_limit\", \"pressure_vanished\", "
                    "\"non_positive_curvature\" or \"coupling_limit\"")
      .def_readonly("touches_boundary", &PyContactResult::touches_boundary,
                    "pressure on a border cell: the domain is too small")
      .def_readonly("max_penetration", &PyContactResult::max_penetration,
                    "largest overlap max(0, -min(gap)) [m]; 0 when no cell interpenetrates")
      .def_readonly("warning", &PyContactResult::warning)
      .def_readonly("friction_coupling", &PyContactResult::friction_coupling,
                    "solve_sliding's coupling, as summary.json's friction_coupling: solves, "
                    "pressure_change, pressure_shift, centroid_shift [m], converged; None "
                    "otherwise")
      .def_readonly("plastic_depth", &PyContactResult::plastic_depth,
                    "with hardness: the plastic depth [m] (ny, nx), the overlap of the cells at "
                    "the hardness (in a sweep accumulated over its steps); None otherwise")
      .def_readonly("plastic", &PyContactResult::plastic,
                    "with hardness: summary.json's plastic (hardness, plastic_area, "
                    "plastic_area_fraction, max_plastic_depth, plastic_volume); None otherwise")
      .def_readonly("cohesive_area", &PyContactResult::cohesive_area,
                    "with adhesion: the cells under the cohesive stress off contact [m^2]; None "
                    "otherwise")
      .def_readonly("jumped_off", &PyContactResult::jumped_off,
                    "with adhesion, in a sweep: the contact of the step before ended here; None "
                    "otherwise")
      .def_readonly("phase", &PyContactResult::phase,
                    "in a sweep: \"load\" or \"unload\" (sweep.csv's phase); None otherwise")
      .def("__repr__", [](const PyContactResult& r) {
        return py::str(
                   "ContactResult(status={!r}, iterations={}, load={!r}, contact_area={!r}, "
                   "max_pressure={!r})")
            .format(r.status, r.iterations, r.load, r.contact_area, r.max_pressure);
      });
  m.def("solve_contact", &solve_contact, "op"_a, "height"_a, py::kw_only(), "load"_a = py::none(),
        "approach"_a = py::none(), "tolerance"_a = 1e-10, "max_iterations"_a = 1000,
        "preconditioned"_a = true, "hardness"_a = py::none(), "adhesion"_a = py::none(),
        "work_of_adhesion"_a = py::none(), "adhesion_range"_a = py::none(),
        "Frictionless normal contact of a rigid indenter of initial separation `height` [m] "
        "(ny, nx) on the operator's body, under a total load [N] or an approach [m]; with "
        "`hardness` [Pa] the pressure capped at it, the overlap there plastic (docs/contact.md, "
        "'Hardness'); with adhesion=\"dugdale\", work_of_adhesion [J/m^2] and adhesion_range [m] "
        "a Dugdale cohesive zone (docs/contact.md, 'Adhesion': loads may be tensile, "
        "approaches zero or negative).");
  m.def("solve_sliding", &solve_sliding, "op"_a, "height"_a, "body"_a, py::kw_only(), "friction"_a,
        "load"_a = py::none(), "approach"_a = py::none(), "tolerance"_a = 1e-10,
        "max_iterations"_a = 1000, "preconditioned"_a = true, "threads"_a = 1,
        "solve_contact under full sliding along +x: the surface of `body` (a LayerStack with "
        "bonded interfaces, or a Material: the operator's body) receives q_x = friction p, "
        "whose normal displacement enters the gap; the normal contact is solved again until "
        "the pressure changes by less than ten times `tolerance` (a scene's [contact] "
        "friction; docs/contact.md). The result's friction_coupling reports it.");
  m.def("solve_sweep", &solve_sweep, "op"_a, "height"_a, py::kw_only(), "loads"_a = py::none(),
        "approaches"_a = py::none(), "tolerance"_a = 1e-10, "max_iterations"_a = 1000,
        "preconditioned"_a = true, "hardness"_a = py::none(), "unload"_a = false,
        "adhesion"_a = py::none(), "work_of_adhesion"_a = py::none(),
        "adhesion_range"_a = py::none(),
        "solve_contact at every load [N] (or approach [m]) of a list, on one operator: a list "
        "of ContactResult in ascending order of the values, each solve started from the ones "
        "before it (fewer operator applications than separate solves; docs/contact.md, "
        "'Sweeps'). With `hardness` the sweep is a loading history (the plastic depth kept); "
        "`unload=True` then adds the values below the largest, descending. With adhesion each "
        "value starts from the state before it (the branch through pull-off).");
  m.def("residual_gap", &residual_gap_of, "height"_a, "plastic_depth"_a,
        "The gap the permanent surface leaves at zero load: height + plastic_depth less its "
        "minimum [m] (a scene's residual_gap.npy).");
}

}  // namespace coatfft::python
