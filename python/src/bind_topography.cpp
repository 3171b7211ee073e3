// Measured topographies: coatfft.read_topography, the readers of `coatfft topography` and of a
// scene's [contact] topography (topography/topography.hpp), not a second copy (docs/python.md).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "scene/resources.hpp"
#include "surfaces/detrend.hpp"
#include "topography/topography.hpp"
#include "topography/topography_summary.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

py::object optional_object(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

py::dict read_topography(const std::filesystem::path& path, std::optional<std::string> unit,
                         const std::string& detrend, const std::string& missing,
                         std::optional<std::string> max_memory) {
  topography::ReadOptions options;
  options.fill_hint = "missing='fill'";
  if (max_memory)
    options.max_memory = scene::parse_memory_size(*max_memory, "read_topography: max_memory");
  options.unit = unit.value_or("");
  options.missing = topography::missing_points_from_name(missing, "read_topography: missing");
  const Detrend how = detrend_from_name(detrend, "read_topography: detrend");
  topography::Topography t = topography::read_topography(path, options);
  Field heights = detrended(topography::topography_grid(path, t), t.heights, how);
  topography::require_finite_map(path, heights, "the detrended map");
  py::dict metadata;
  for (const auto& [name, value] : t.metadata) metadata[py::str(name)] = py::str(value);
  return py::dict(
      "heights"_a = array_from_field(std::move(heights)), "lx"_a = optional_object(t.lx),
      "ly"_a = optional_object(t.ly),
      "periodic"_a = t.periodic ? py::object(py::bool_(*t.periodic)) : py::object(py::none()),
      "format"_a = t.format,
      "unit"_a = t.unit.empty() ? py::object(py::none()) : py::object(py::str(t.unit)),
      "missing"_a = t.missing, "metadata"_a = metadata);
}

}  // namespace

void bind_topography(py::module_& m) {
  m.def("read_topography", &read_topography, "path"_a, "unit"_a = py::none(), "detrend"_a = "none",
        "missing"_a = "refuse", "max_memory"_a = py::none(),
        "A measured topography (.npy, .csv/.txt/.asc/.xyz, .nc, .x3p, .sdf) as `coatfft "
        "topography` reads it (docs/measured_surfaces.md): a dict of heights [m], shape (ny, nx), "
        "less the mean or plane asked for by `detrend` ('none', 'mean', 'plane'); lx and ly [m] "
        "(None when the file carries no size); periodic (None when the file does not say); "
        "format; unit (the file's, or `unit` for a file that carries none: 'm', 'mm', 'um', "
        "'nm', 'A'); missing (points the file marks missing: refused unless missing='fill', "
        "which fills them by harmonic interpolation); metadata (what the file says of itself). "
        "max_memory ('4G', as the program's --max-memory; default: what the machine has) bounds "
        "the memory reading and filling the map may take: a larger map is refused first.");
}

}  // namespace coatfft::python
