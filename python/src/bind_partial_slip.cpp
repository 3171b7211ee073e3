// solve_partial_slip: a partial slip (contact/partial_slip.hpp) on an Operator, through the scene
// layer's steps and report (scene/partial_slip_run.hpp), so that its numbers are the program's.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "contact/partial_slip.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "operator.hpp"
#include "scene/partial_slip_run.hpp"
#include "scene/scene_run.hpp"
#include "solve_setup.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

using Values = std::variant<double, std::vector<double>>;

// A partial slip's result: the last step's normal fields, the tractions, slip and stick zone
// (stacked one per step for a path), and the summary's reports as dicts.
struct PyPartialSlip {
  py::array_t<double> pressure, displacement, gap;
  py::array shear_x, shear_y, slip_x, slip_y, stick;
  py::dict summary;     // summary.json's "partial_slip"
  py::object fretting;  // its "fretting" for a path, else None
  bool converged = false;
  std::string warning;
};

// The scene's [contact] keys of a partial slip, which the scene layer's steps read.
scene::ContactSpec partial_slip_spec(double friction, const Values& values, bool by_load,
                                     std::optional<double> load, std::optional<double> approach,
                                     double tolerance) {
  scene::ContactSpec spec;
  spec.friction = friction;
  spec.load = load;
  spec.approach = approach;
  spec.tolerance = tolerance;
  spec.tangential_control = by_load ? TangentialControl::load : TangentialControl::shift;
  spec.tangential_path = std::holds_alternative<std::vector<double>>(values);
  spec.tangential = spec.tangential_path ? std::get<std::vector<double>>(values)
                                         : std::vector<double>{std::get<double>(values)};
  COATFFT_REQUIRE(!spec.tangential.empty(), "solve_partial_slip: an empty path");
  return spec;
}

PyPartialSlip solve_partial_slip(Operator& op, const DoubleArray& height, py::handle body_object,
                                 double friction, std::optional<Values> tangential_load,
                                 std::optional<Values> tangential_shift, std::optional<double> load,
                                 std::optional<double> approach, double tolerance,
                                 int max_iterations, int threads) {
  COATFFT_REQUIRE(load.has_value() != approach.has_value(),
                  "solve_partial_slip: give exactly one of load [N] and approach [m]");
  COATFFT_REQUIRE(tangential_load.has_value() != tangential_shift.has_value(),
                  "solve_partial_slip: give exactly one of tangential_load [N] and "
                  "tangential_shift [m]");
  COATFFT_REQUIRE(std::isfinite(friction) && friction > 0.0 && friction <= 10.0,
                  "solve_partial_slip: friction = ", friction, " must be in (0, 10]");
  const LayerStack body =
      layers_of(body_object, "solve_partial_slip", "the tractions' response needs the layers");
  require_operator_body(op, body, "solve_partial_slip");
  const Field h = field_from_array(height, op.grid(), "solve_partial_slip: height");
  const scene::ContactSpec spec =
      partial_slip_spec(friction, tangential_load ? *tangential_load : *tangential_shift,
                        tangential_load.has_value(), load, approach, tolerance);
  const ContactOptions options = contact_options(op, approach.has_value(), tolerance,
                                                 max_iterations, true, "solve_partial_slip");
  std::vector<PartialSlipResult> steps = without_gil([&] {
    const auto guard = op.lock();
    RelativeSurfaceResponse response(surface_response(op, body, threads));
    ContactSolver solver(op.op(), options);
    scene::ProgressObserver silent;
    return scene::solve_scene_partial_slip(solver, response, spec, h, silent);
  });
  ContactResult last = steps.back().normal;
  scene::PartialSlipReport report = scene::report_partial_slip(steps, spec);
  PyPartialSlip out;
  out.pressure = array_from_field(std::move(last.pressure));
  out.displacement = array_from_field(std::move(last.displacement));
  out.gap = array_from_field(std::move(last.gap));
  const scene::PartialSlipFields& f = report.fields;
  const bool path = spec.tangential_path;
  out.shear_x = stacked_array(f.shear_x, path);
  out.shear_y = stacked_array(f.shear_y, path);
  out.slip_x = stacked_array(f.slip_x, path);
  out.slip_y = stacked_array(f.slip_y, path);
  out.stick = stacked_array(f.stick, path);
  out.summary = dict_from_json_text(report.partial_slip.dump());
  out.fretting = report.fretting.is_null()
                     ? py::object(py::none())
                     : py::object(dict_from_json_text(report.fretting.dump()));
  out.converged = report.converged;
  out.warning = report.warning;
  return out;
}

}  // namespace

void bind_partial_slip(py::module_& m) {
  py::class_<PyPartialSlip>(m, "PartialSlipResult",
                            "A partial slip: fields (ny, nx), or (steps, ny, nx) for a path")
      .def_readonly("pressure", &PyPartialSlip::pressure, "p [Pa] of the last step")
      .def_readonly("displacement", &PyPartialSlip::displacement,
                    "u_z [m] of the last step, the tractions' share included")
      .def_readonly("gap", &PyPartialSlip::gap, "[m] of the last step")
      .def_readonly("shear_x", &PyPartialSlip::shear_x, "q_x [Pa] the body's surface receives")
      .def_readonly("shear_y", &PyPartialSlip::shear_y, "q_y [Pa]")
      .def_readonly("slip_x", &PyPartialSlip::slip_x, "slip over the step along x [m]")
      .def_readonly("slip_y", &PyPartialSlip::slip_y, "slip over the step along y [m]")
      .def_readonly("stick", &PyPartialSlip::stick, "uint8: 1 where the contact sticks")
      .def_readonly("summary", &PyPartialSlip::summary,
                    "summary.json's partial_slip: the last step's numbers")
      .def_readonly("fretting", &PyPartialSlip::fretting,
                    "summary.json's fretting for a path (steps: fretting.csv's rows, loops), "
                    "else None")
      .def_readonly("converged", &PyPartialSlip::converged, "every step converged")
      .def_readonly("warning", &PyPartialSlip::warning, "the first step that did not, and why");
  m.def("solve_partial_slip", &solve_partial_slip, "op"_a, "height"_a, "body"_a, py::kw_only(),
        "friction"_a, "tangential_load"_a = py::none(), "tangential_shift"_a = py::none(),
        "load"_a = py::none(), "approach"_a = py::none(), "tolerance"_a = 1e-10,
        "max_iterations"_a = 1000, "threads"_a = 1,
        "Partial slip of a rigid indenter of separation `height` [m] on `body` (a LayerStack "
        "with bonded interfaces, or a Material: the operator's body), pressed with a load [N] "
        "or an approach [m] and moved along +x under a tangential_load [N] (|Q| < friction x "
        "load) or a tangential_shift [m]: one value, or a list (a fretting path, solved in the "
        "order given, its fields stacked). As a scene's [contact] tangential_load or "
        "tangential_shift (docs/contact.md, 'Partial slip').");
}

}  // namespace coatfft::python
