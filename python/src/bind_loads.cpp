// The grid, the known pressures and the references they are checked against: Grid,
// hertz_pressure, uniform_disk_pressure, hertz_displacement, uniform_disk_displacement,
// hankel_displacement.
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "load_names.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/load_limits.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "validation/hankel_displacement.hpp"
#include "validation/hertz.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

Sampling parse_sampling(std::string_view name) {
  if (name == "centre") return Sampling::centre;
  if (name == "cell_average") return Sampling::cell_average;
  throw InvalidArgument(
      detail::concat("sampling = \"", name, "\" is not one of \"centre\", \"cell_average\""));
}

AxisymmetricLoad parse_load(std::string_view name) {
  if (name == "hertz") return AxisymmetricLoad::hertz;
  if (name == "uniform_disk") return AxisymmetricLoad::uniform_disk;
  throw InvalidArgument(
      detail::concat("load = \"", name, "\" is not one of \"hertz\", \"uniform_disk\""));
}

namespace {

// f(r) at every radius of an array (any shape), without the GIL: radius by radius.
template <typename Function>
py::array_t<double> at_radii(const DoubleArray& r, Function&& f) {
  std::vector<double> u(static_cast<std::size_t>(r.size()));
  const double* radii = r.data();
  without_gil([&] {
    // A Hankel reference integrates per radius: many radii take seconds.
    for (std::size_t i = 0; i < u.size(); ++i) {
      check_interrupt();
      u[i] = f(radii[i]);
    }
  });
  return array_like(r, std::move(u));
}

py::array_t<double> coordinates(std::ptrdiff_t n, const std::function<double(std::ptrdiff_t)>& c) {
  std::vector<double> values(static_cast<std::size_t>(n));
  for (std::ptrdiff_t i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = c(i);
  return py::array_t<double>(static_cast<py::ssize_t>(n), values.data());
}

void bind_grid(py::module_& m) {
  py::class_<Grid>(m, "Grid", "nx x ny cells covering [-lx/2, lx/2] x [-ly/2, ly/2] [m].")
      .def(py::init<std::ptrdiff_t, std::ptrdiff_t, double, double>(), "nx"_a, "ny"_a, "lx"_a,
           "ly"_a)
      .def_property_readonly("nx", &Grid::nx)
      .def_property_readonly("ny", &Grid::ny)
      .def_property_readonly("lx", &Grid::lx, "[m]")
      .def_property_readonly("ly", &Grid::ly, "[m]")
      .def_property_readonly("dx", &Grid::dx, "cell size along x [m]")
      .def_property_readonly("dy", &Grid::dy, "cell size along y [m]")
      .def_property_readonly(
          "shape", [](const Grid& g) { return py::make_tuple(g.ny(), g.nx()); },
          "(ny, nx): the shape of every field on the grid")
      .def_property_readonly(
          "x", [](const Grid& g) { return coordinates(g.nx(), [&](auto i) { return g.x(i); }); },
          "cell centres along x [m], shape (nx,)")
      .def_property_readonly(
          "y", [](const Grid& g) { return coordinates(g.ny(), [&](auto j) { return g.y(j); }); },
          "cell centres along y [m], shape (ny,)")
      // is_operator: another type gives NotImplemented, so that g == 3 is False, not TypeError.
      .def(
          "__eq__", [](const Grid& a, const Grid& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const Grid& g) {
        return py::str("Grid(nx={}, ny={}, lx={!r}, ly={!r})")
            .format(g.nx(), g.ny(), g.lx(), g.ly());
      });
}

void bind_pressures(py::module_& m) {
  m.def(
      "hertz_pressure",
      [](const Grid& grid, double p0, double a, std::string_view sampling) {
        const Sampling s = parse_sampling(sampling);
        require_disk_load(grid, p0, a, s, {"hertz_pressure: p0", "hertz_pressure: a", "grid"});
        require_grid_memory(grid.nx(), grid.ny(), 1.0, "hertz_pressure");
        return array_from_field(hertz_pressure(grid, p0, a, s));
      },
      "grid"_a, "p0"_a, "a"_a, "sampling"_a = "centre",
      "p0 sqrt(1 - r^2/a^2) [Pa] on r < a, shape (ny, nx); sampling \"centre\" or "
      "\"cell_average\".");
  m.def(
      "uniform_disk_pressure",
      [](const Grid& grid, double p, double a, std::string_view sampling) {
        const Sampling s = parse_sampling(sampling);
        require_disk_load(grid, p, a, s,
                          {"uniform_disk_pressure: p", "uniform_disk_pressure: a", "grid"});
        require_grid_memory(grid.nx(), grid.ny(), 1.0, "uniform_disk_pressure");
        return array_from_field(uniform_disk_pressure(grid, p, a, s));
      },
      "grid"_a, "p"_a, "a"_a, "sampling"_a = "centre",
      "p [Pa] on r < a, shape (ny, nx); sampling \"centre\" or \"cell_average\".");
}

void bind_references(py::module_& m) {
  m.def(
      "hertz_displacement",
      [](const DoubleArray& r, double p0, double a, double E_star) {
        return at_radii(r, [&](double ri) { return hertz_displacement(ri, p0, a, E_star); });
      },
      "r"_a, "p0"_a, "a"_a, "E_star"_a,
      "Closed-form u_z(r) [m] of a half-space of plane-strain modulus E_star [Pa] under the "
      "Hertz pressure (Johnson eq. 3.41), at every r [m] of an array.");
  m.def(
      "uniform_disk_displacement",
      [](const DoubleArray& r, double p, double a, double E_star) {
        return at_radii(r, [&](double ri) { return uniform_disk_displacement(ri, p, a, E_star); });
      },
      "r"_a, "p"_a, "a"_a, "E_star"_a,
      "Closed-form u_z(r) [m] of a half-space under a uniform pressure p [Pa] on r < a.");
  m.def(
      "hankel_displacement",
      [](py::handle body, const DoubleArray& r, double amplitude, double a, std::string_view load,
         double rel_tol) {
        const AxisymmetricLoad shape = parse_load(load);
        const std::shared_ptr<const Frf> frf = body_from_object(body).response();
        return at_radii(r, [&](double ri) {
          return hankel_displacement(*frf, shape, amplitude, a, ri, rel_tol);
        });
      },
      "body"_a, "r"_a, "amplitude"_a, "a"_a, "load"_a = "hertz", "rel_tol"_a = 1e-10,
      "u_z(r) [m] of any body under an axisymmetric load (\"hertz\": amplitude = p0, "
      "\"uniform_disk\": amplitude = p) as a Hankel integral of its FRF, at every r [m].");
}

}  // namespace

void bind_loads(py::module_& m) {
  bind_grid(m);
  bind_pressures(m);
  bind_references(m);
}

}  // namespace coatfft::python
