// make_operator and Operator: the library's operator factory (convolution/make_operator.hpp) with
// the scene's [method] options as keywords, and name = "auto" (docs/auto.md) as the default.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "bindings.hpp"
#include "bodies.hpp"
#include "cli/automatic_method.hpp"
#include "cli/operator_from_scene.hpp"
#include "convolution/fftw_wisdom.hpp"
#include "core/detail/parse_name.hpp"
#include "core/threads.hpp"
#include "operator.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

py::array_t<double> Operator::apply(const DoubleArray& pressure) {
  Field p = field_from_array(pressure, grid(), "apply: pressure");
  Field u;
  {
    py::gil_scoped_release release;
    const auto guard = lock();
    built_.op->apply(p, u);
  }
  // Finite pressures can still overflow: |u| ~ p L / E*.
  COATFFT_REQUIRE(u.allFinite(),
                  "apply: the displacement overflows double precision; rescale "
                  "the units of the pressure and the moduli");
  return array_from_field(std::move(u));
}

namespace {

// The keywords of make_operator, as the scene's [method] keys (docs/scene_format.md).
struct MethodKeywords {
  std::string method;
  std::optional<double> tolerance, alpha, g0_tol, load_radius;
  std::optional<std::string> g0;
  std::string planning;
  std::optional<int> threads;
  double applications;
};

// The keyword `name` refused for `method`, with the scene reader's reasons.
void refuse_if(bool given, const char* name, const std::string& method, const char* why) {
  COATFFT_REQUIRE(!given, "make_operator: ", name, " applies only to ", why, ", not to method = \"",
                  method, "\"");
}

OperatorOptions named_options(const Grid& grid, const MethodKeywords& k) {
  OperatorOptions o;
  try {
    o.method = parse_method(k.method);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(detail::concat("make_operator: method = ", e.what(), " or \"auto\""));
  }
  const bool pipeline = samples_frf_lattice(o.method);
  refuse_if(k.tolerance.has_value(), "tolerance", k.method, "method = \"auto\"");
  refuse_if(k.load_radius.has_value(), "load_radius", k.method, "method = \"auto\"");
  for (const auto& [given, name] :
       {std::pair{k.alpha.has_value(), "alpha"}, std::pair{k.g0.has_value(), "g0"},
        std::pair{k.g0_tol.has_value(), "g0_tol"}})
    refuse_if(given && !pipeline, name, k.method, "\"frf-spectral\" and \"frf-dcfft\"");
  o.alpha = k.alpha.value_or(o.alpha);
  if (k.g0)
    o.g0 = detail::parse_name(
        *k.g0, std::array{G0Method::regularized, G0Method::quadrature, G0Method::omitted});
  o.g0_tolerance = k.g0_tol.value_or(o.g0_tolerance);
  o.planning = parse_planning(k.planning);
  o.threads = k.threads.value_or(1);
  check_operator_options(grid, o);
  return o;
}

// FFTW's first plan in a process costs milliseconds once (model/cost_model.hpp): only the first
// operator of a Python session pays it.
bool first_operator = true;

cli::AutomaticChoice automatic_choice(const Grid& grid, const Body& body, const MethodKeywords& k) {
  for (const auto& [given, name] :
       {std::pair{k.alpha.has_value(), "alpha"}, std::pair{k.g0.has_value(), "g0"},
        std::pair{k.g0_tol.has_value(), "g0_tol"}})
    refuse_if(given, name, "auto", "the named methods \"frf-spectral\" and \"frf-dcfft\"");
  AutoRequest request;
  request.tolerance = k.tolerance.value_or(request.tolerance);
  COATFFT_REQUIRE(request.tolerance >= 1e-12 && request.tolerance <= 0.1,
                  "make_operator: tolerance = ", request.tolerance, " must be in [1e-12, 0.1]");
  request.applications = k.applications;
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  request.max_threads = k.threads.value_or(std::clamp(cores, 1, max_threads));
  request.planning = parse_planning(k.planning);
  request.first_in_process = first_operator;
  std::vector<ReferenceLoad> loads = cli::unknown_load_references(grid);
  if (k.load_radius) {
    COATFFT_REQUIRE(std::isfinite(*k.load_radius) && *k.load_radius > 0,
                    "make_operator: load_radius = ", *k.load_radius, " m must be finite and > 0");
    loads = {{AxisymmetricLoad::hertz, std::max(*k.load_radius, 0.5 * grid.dx())}};
  }
  py::gil_scoped_release release;
  return body.frf ? cli::choose_automatically(grid, *body.frf, loads, request)
                  : cli::choose_automatically(grid, *body.stack, loads, request);
}

py::dict report_dict(const Grid& grid, const BuiltOperator& built, const MethodKeywords& k,
                     const std::optional<cli::AutomaticChoice>& choice) {
  nlohmann::json json = cli::operator_report_json(built.report);
  json["method"] = to_string(built.report.method);
  json["method_requested"] = k.method;
  json["nx"] = grid.nx();
  json["ny"] = grid.ny();
  json["fft_nx"] = built.report.fft_nx;
  json["fft_ny"] = built.report.fft_ny;
  json["setup_seconds"] = built.report.setup_seconds;
  json["kernel_seconds"] = built.report.kernel_seconds;
  json["warnings"] = cli::operator_warnings(built.report);
  if (choice) json["auto"] = cli::automatic_choice_json(*choice, *k.tolerance);
  return dict_from_json_text(json.dump());
}

std::unique_ptr<Operator> make_operator_py(const Grid& grid, py::handle body_object,
                                           MethodKeywords k) {
  const Body body = body_from_object(body_object);
  std::optional<cli::AutomaticChoice> choice;
  OperatorOptions options;
  const LayerStack* stack = body.stack ? &*body.stack : nullptr;
  if (k.method == "auto") {
    k.tolerance = k.tolerance.value_or(AutoRequest{}.tolerance);
    choice = automatic_choice(grid, body, k);
    options = choice->method.options;
    if (choice->reduction) stack = &choice->reduction->body;
  } else {
    options = named_options(grid, k);
  }
  BuiltOperator built;
  {
    py::gil_scoped_release release;
    built = stack ? make_operator(grid, *stack, options) : make_operator(grid, *body.frf, options);
  }
  first_operator = false;
  cli::refuse_untrustworthy(built.report);
  py::dict report = report_dict(grid, built, k, choice);
  warn_each(report["warnings"]);
  return std::make_unique<Operator>(std::move(built), std::move(report));
}

}  // namespace

void bind_operator(py::module_& m) {
  py::class_<Operator>(m, "Operator", "The surface-displacement operator of a body on a grid.")
      .def("apply", &Operator::apply, "p"_a,
           "u [m, positive into the body] of the pressure p [Pa], arrays of shape (ny, nx).")
      .def("__call__", &Operator::apply, "p"_a)
      .def_property_readonly("grid", &Operator::grid)
      // A copy: the operator's own report (which solve_contact reads) stays as built.
      .def_property_readonly(
          "report",
          [](const Operator& o) {
            return py::module_::import("copy").attr("deepcopy")(o.report());
          },
          "method, timings [s], FFT sizes, g(0), the automatic choice, ... (a copy)")
      .def_property_readonly("method", [](const Operator& o) { return o.method(); });
  m.def(
      "make_operator",
      [](const Grid& grid, py::handle body, std::string method, std::optional<double> tolerance,
         std::optional<double> alpha, std::optional<std::string> g0, std::optional<double> g0_tol,
         std::string planning, std::optional<int> threads, double applications,
         std::optional<double> load_radius) {
        return make_operator_py(grid, body,
                                {std::move(method), tolerance, alpha, g0_tol, load_radius,
                                 std::move(g0), std::move(planning), threads, applications});
      },
      "grid"_a, "body"_a, py::kw_only(), "method"_a = "auto", "tolerance"_a = py::none(),
      "alpha"_a = py::none(), "g0"_a = py::none(), "g0_tol"_a = py::none(),
      "planning"_a = "estimate", "threads"_a = py::none(), "applications"_a = 1.0,
      "load_radius"_a = py::none(),
      "The operator of `body` (LayerStack, Material or Frf) on `grid`; keywords as the scene's "
      "[method] keys (docs/python.md).");
}

}  // namespace coatfft::python
