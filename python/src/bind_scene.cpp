// Scenes and FRF checks as the command line has them: run_scene (what `coatfft run` computes,
// without writing files) and validate_frf (the checks of `coatfft validate-frf`).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <tuple>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "core/error.hpp"
#include "load_names.hpp"
#include "scene/frf_validation.hpp"
#include "scene/scene_run.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

// The arrays of a [stress] scene, shaped as the program's stress.npy, von_mises.npy,
// stress_section.npy, von_mises_section.npy, stress_interfaces.npy and von_mises_interfaces.npy.
void add_stress_arrays(const Grid& grid, const scene::StressRun& s, py::dict& out) {
  const auto as_array = [](const std::vector<double>& v, std::vector<py::ssize_t> shape) {
    py::array_t<double> a(shape);
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  const py::ssize_t nx = grid.nx(), ny = grid.ny();
  const auto n = static_cast<py::ssize_t>(s.depth_planes);
  const auto nz = static_cast<py::ssize_t>(s.section_rows);
  const auto ni = static_cast<py::ssize_t>(s.interface_count);
  // Those the scene's [output] fields keep (every one by default), as the program writes them.
  const std::array<std::tuple<const char*, const std::vector<double>*, std::vector<py::ssize_t>>, 6>
      arrays{{{"stress", &s.stress, {n, 6, ny, nx}},
              {"von_mises", &s.von_mises, {n, ny, nx}},
              {"stress_section", &s.section, {nz, 6, nx}},
              {"von_mises_section", &s.section_von_mises, {nz, nx}},
              {"stress_interfaces", &s.interfaces, {ni, 2, 6, ny, nx}},
              {"von_mises_interfaces", &s.interfaces_von_mises, {ni, 2, ny, nx}}}};
  for (const auto& [name, values, shape] : arrays)
    if (!values->empty()) out[name] = as_array(*values, shape);
}

// The path as a str or any os.PathLike (pathlib.Path), as Python's own file functions take it.
py::dict run_scene(const std::filesystem::path& path) {
  scene::SceneRun run = without_gil([&] { return scene::run_scene(path); });
  py::dict out;
  if (run.sweep) {
    out["uz"] = stacked_array(run.sweep->uz, true);
    out["pressure"] = stacked_array(run.sweep->pressure, true);
    out["gap"] = stacked_array(run.sweep->gap, true);
    if (!run.sweep->plastic.empty()) out["plastic"] = stacked_array(run.sweep->plastic, true);
  } else {
    out["uz"] = array_from_field(std::move(run.uz));
    out["pressure"] = array_from_field(std::move(run.pressure));
    if (run.gap) out["gap"] = array_from_field(std::move(*run.gap));
    if (run.plastic) out["plastic"] = array_from_field(std::move(*run.plastic));
  }
  if (run.residual_gap) out["residual_gap"] = array_from_field(std::move(*run.residual_gap));
  if (run.stress) add_stress_arrays(run.grid, *run.stress, out);
  if (run.ux) out["ux"] = array_from_field(std::move(*run.ux));
  if (run.uy) out["uy"] = array_from_field(std::move(*run.uy));
  if (run.partial_slip) {  // a path's stacked, as its .npy files
    const bool stacked = run.summary.contains("fretting");
    const scene::PartialSlipFields& f = *run.partial_slip;
    out["shear_x"] = stacked_array(f.shear_x, stacked);
    out["shear_y"] = stacked_array(f.shear_y, stacked);
    out["slip_x"] = stacked_array(f.slip_x, stacked);
    out["slip_y"] = stacked_array(f.slip_y, stacked);
    out["stick"] = stacked_array(f.stick, stacked);
  }
  out["summary"] = dict_from_json_text(run.summary.dump());
  return out;
}

// The load of the displacement checks, as a scene's [pressure] gives it to the command: none
// (the default loads), or a shape with its amplitude [Pa], radius [m] and sampling.
scene::FrfValidationOptions validation_options(const std::optional<std::string>& load,
                                               double amplitude, std::optional<double> radius,
                                               const std::string& sampling) {
  scene::FrfValidationOptions options;
  COATFFT_REQUIRE(load.has_value() == radius.has_value(),
                  "validate_frf: give load and load_radius together (or neither, for the default "
                  "loads)");
  if (load)
    options.load =
        scene::FrfCheckLoad{parse_load(*load), amplitude, *radius, parse_sampling(sampling)};
  return options;
}

py::dict validate_frf(py::handle frf_object, py::handle claim_object, const Grid& grid,
                      double tolerance, const std::optional<std::string>& load, double amplitude,
                      std::optional<double> load_radius, const std::string& sampling) {
  // The command's own check names its --tolerance flag; Python names the keyword.
  COATFFT_REQUIRE(tolerance > 0 && tolerance < 1, "validate_frf: tolerance = ", tolerance,
                  " must be in (0, 1)");
  const Body frf = body_from_object(frf_object, "frf");
  const Body claim = body_from_object(claim_object, "body");
  COATFFT_REQUIRE(claim.stack,
                  "validate_frf: body must be a LayerStack or a Material (what the "
                  "FRF is checked against), not an Frf");
  const scene::FrfValidationOptions options =
      validation_options(load, amplitude, load_radius, sampling);
  const scene::FrfValidation result = without_gil(
      [&] { return scene::validate_frf(*frf.response(), *claim.stack, grid, tolerance, options); });
  py::list checks;
  for (const scene::FrfCheck& c : result.checks)
    checks.append(py::dict("name"_a = c.name, "difference"_a = c.difference,
                           "tolerance"_a = c.tolerance, "passed"_a = c.passed,
                           "detail"_a = c.detail, "reference"_a = c.reference));
  return py::dict("passed"_a = result.passed, "checks"_a = checks,
                  "reference"_a = result.reference);
}

}  // namespace

void bind_scene(py::module_& m) {
  m.def("run_scene", &run_scene, "path"_a,
        "What `coatfft run` computes for the scene file: a dict of arrays (ny, nx) \"uz\", "
        "\"pressure\" (and \"gap\" for a contact) and \"summary\" (summary.json's dict). Writes "
        "nothing.");
  m.def("validate_frf", &validate_frf, "frf"_a, "body"_a, "grid"_a, "tolerance"_a = 1e-6,
        py::kw_only(), "load"_a = py::none(), "amplitude"_a = 1e6, "load_radius"_a = py::none(),
        "sampling"_a = "cell_average",
        "The checks of `coatfft validate-frf`: `frf` against the body it claims to be, on `grid`; "
        "a dict with \"passed\" and the \"checks\". `load` (\"hertz\" or \"uniform_disk\", "
        "with `amplitude` [Pa], `load_radius` [m], `sampling`) replaces the check load of its "
        "kind, as a scene's [pressure] does for the command.");
}

}  // namespace coatfft::python
