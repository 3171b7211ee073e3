// make_operator and Operator: the library's operator factory
// (convolution/operators/make_operator.hpp) with the scene's [method] options as keywords, and name
// = "auto" (docs/auto.md) as the default.
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "bindings.hpp"
#include "bodies.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "model/operator_plan.hpp"
#include "operator.hpp"
#include "scene/automatic_method.hpp"
#include "scene/method_request.hpp"
#include "scene/operator_from_scene.hpp"
#include "scene/scene.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

py::array_t<double> Operator::apply(const DoubleArray& pressure, const py::object& out) {
  check_shape(pressure, grid(), "apply: pressure");
  py::array_t<double> u = output_array(out, grid(), "apply: out");
  double* target = u.mutable_data();
  without_gil([&] {
    const auto guard = lock();
    // The pressure is copied first, so `out` may be the pressure's own array.
    copy_into_field(pressure, pressure_, "apply: pressure");
    built_.op->apply(pressure_, displacement_);
    // Finite pressures can still overflow: |u| ~ p L / E*.
    COATFFT_REQUIRE(displacement_.allFinite(),
                    "apply: the displacement overflows double precision; rescale the units of the "
                    "pressure and the moduli");
    // Only a complete result reaches `out`: an interrupted apply leaves it as it was.
    std::copy_n(displacement_.data(), displacement_.size(), target);
  });
  return u;
}

namespace {

// The keywords of make_operator, as the scene's [method] keys (docs/scene_format.md), and the
// cost model's `applications` and `load_radius` for method = "auto".
struct MethodKeywords {
  std::string method;
  std::string boundary;
  std::optional<double> tolerance, alpha, g0_tol, load_radius, applications;
  std::optional<std::string> g0, planning;
  std::optional<int> threads;
};

// The keywords of make_operator as a MethodRequest, checked by the one check a scene's [method]
// goes through (scene/method_request.hpp). load_radius and applications, the cost model's inputs
// that a scene derives from its load, are Python's own keywords of method = "auto".
scene::MethodSpec method_spec(const MethodKeywords& k) {
  Boundary boundary = Boundary::free;
  try {
    boundary = parse_boundary(k.boundary);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(detail::concat("make_operator: boundary = ", e.what()));
  }
  const bool periodic = boundary == Boundary::periodic;
  for (const auto& [given, name] : {std::pair{k.load_radius.has_value(), "load_radius"},
                                    std::pair{k.applications.has_value(), "applications"}}) {
    COATFFT_REQUIRE(k.method == "auto" || !given, "make_operator: ", name,
                    ": applies only to method = \"auto\", not to method = \"", k.method, "\"");
    COATFFT_REQUIRE(!periodic || !given, "make_operator: ", name,
                    ": applies only to free boundaries: on a periodic one method = \"auto\" "
                    "takes the body's exact method (dcfft or frf-split)");
  }
  scene::MethodRequest r;
  r.boundary = boundary;
  r.name = k.method;
  r.tolerance = k.tolerance;
  r.alpha = k.alpha;
  r.g0 = k.g0;
  r.g0_tol = k.g0_tol;
  r.planning = k.planning;
  if (k.threads) r.threads = *k.threads;
  const auto where = [](std::string_view key) {
    return detail::concat("make_operator: ", key == "name" ? std::string_view("method") : key);
  };
  return scene::method_from_request(r, {where, "method"});
}

// FFTW's first plan in a process costs milliseconds once (model/cost_model.hpp): only the first
// operator of a Python session pays it.
bool first_operator = true;

// The keywords as the library's operator request (model/operator_plan.hpp), which plans a scene's
// operator too: "auto"'s tolerance, applications and reference load, or the named method.
OperatorRequest operator_request(const Grid& grid, const MethodKeywords& k) {
  // Python's operators are for reuse (contact solves, sweeps): the program's contact rule.
  scene::MethodSpec spec = method_spec(k);
  scene::plan_for_repeated_use(spec, grid);
  OperatorRequest request = scene::operator_request(spec);
  AutoRequest& choice = request.automatic_request;
  choice.applications = k.applications.value_or(1.0);
  COATFFT_REQUIRE(choice.applications >= 1 && std::isfinite(choice.applications),
                  "make_operator: applications = ", choice.applications,
                  " must be finite and >= 1");
  choice.first_in_process = first_operator;
  if (k.load_radius) {
    require_load_radius(grid, *k.load_radius, "make_operator: load_radius");
    request.loads = {{AxisymmetricLoad::hertz, std::max(*k.load_radius, 0.5 * grid.dx())}};
  }
  // The memory check counts the fields the module holds beside the operator: the pressure and the
  // displacement of apply.
  request.other_bytes = 2.0 * 8.0 * static_cast<double>(grid.nb_cells());
  request.memory_who = "make_operator";
  return request;
}

py::dict report_dict(const Grid& grid, const BuiltOperator& built, const MethodKeywords& k,
                     const std::optional<AutomaticChoice>& choice, double choice_tolerance) {
  nlohmann::json json = scene::operator_report_json(built.report);
  json["method"] = to_string(built.report.method);
  json["method_requested"] = k.method;
  json["boundary"] = k.boundary;
  json["nx"] = grid.nx();
  json["ny"] = grid.ny();
  json["fft_nx"] = built.report.fft_nx;
  json["fft_ny"] = built.report.fft_ny;
  json["setup_seconds"] = built.report.setup_seconds;
  json["kernel_seconds"] = built.report.kernel_seconds;
  json["warnings"] = operator_warnings(built.report);
  if (choice) json["auto"] = scene::automatic_choice_json(*choice, choice_tolerance);
  return dict_from_json_text(json.dump());
}

std::unique_ptr<Operator> make_operator_py(const Grid& grid, py::handle body_object,
                                           const MethodKeywords& k) {
  const Body body = body_from_object(body_object);
  const OperatorRequest request = operator_request(grid, k);
  const OperatorPlan plan = without_gil([&] {
    return body.stack ? plan_operator(grid, *body.stack, request)
                      : plan_operator(grid, *body.frf, request);
  });
  BuiltOperator built = without_gil([&] {
    return body.stack ? build_operator(grid, *body.stack, plan, "make_operator: method")
                      : build_operator(grid, *body.frf, plan, "make_operator: method");
  });
  first_operator = false;
  py::dict report = report_dict(grid, built, k, plan.choice, request.automatic_request.tolerance);
  warn_each(report["warnings"]);
  return std::make_unique<Operator>(std::move(built), std::move(report), plan.options.threads,
                                    body.response());
}

}  // namespace

void bind_operator(py::module_& m) {
  py::class_<Operator>(m, "Operator", "The surface-displacement operator of a body on a grid.")
      .def("apply", &Operator::apply, "p"_a, "out"_a = py::none(),
           "u [m, positive into the body] of the pressure p [Pa], arrays of shape (ny, nx); "
           "written into `out` (a float64 C-contiguous array) when given.")
      .def("__call__", &Operator::apply, "p"_a, "out"_a = py::none())
      .def_property_readonly("grid", &Operator::grid)
      // A copy: the operator's own report (which solve_contact reads) stays as built.
      .def_property_readonly(
          "report",
          [](const Operator& o) {
            return py::module_::import("copy").attr("deepcopy")(o.report());
          },
          "method, timings [s], FFT sizes, g(0), the automatic choice, ... (a copy)")
      .def_property_readonly("method", [](const Operator& o) { return o.method(); })
      .def("__repr__", [](const Operator& o) {
        return py::str("Operator(method={!r}, grid={!r})").format(o.method(), py::cast(o.grid()));
      });
  m.def(
      "make_operator",
      [](const Grid& grid, py::handle body, std::string method, std::string boundary,
         std::optional<double> tolerance, std::optional<double> alpha,
         std::optional<std::string> g0, std::optional<double> g0_tol,
         std::optional<std::string> planning, std::optional<int> threads,
         std::optional<double> applications, std::optional<double> load_radius) {
        return make_operator_py(
            grid, body,
            {std::move(method), std::move(boundary), tolerance, alpha, g0_tol, load_radius,
             applications, std::move(g0), std::move(planning), threads});
      },
      "grid"_a, "body"_a, py::kw_only(), "method"_a = "auto", "boundary"_a = "free",
      "tolerance"_a = py::none(), "alpha"_a = py::none(), "g0"_a = py::none(),
      "g0_tol"_a = py::none(), "planning"_a = py::none(), "threads"_a = py::none(),
      "applications"_a = py::none(), "load_radius"_a = py::none(),
      "The operator of `body` (LayerStack, Material or Frf) on `grid`; keywords as the scene's "
      "[method] keys, and boundary = \"free\" or \"periodic\" as [grid] boundary "
      "(docs/python.md).");
}

}  // namespace coatfft::python
