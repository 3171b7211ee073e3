// Rough surfaces, indenter shapes and Hertz's closed forms: what a contact script builds its gap
// from, as the program's `coatfft surface` and [contact] indenters do (docs/python.md).
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "contact/indenter.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "surfaces/self_affine_surface.hpp"
#include "validation/hertz_contact.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

// A seed of 0 .. 2^64 - 1, as `coatfft surface --seed` takes it (a Python int of any size).
std::uint64_t seed_of(const py::int_& seed) {
  const unsigned long long value = PyLong_AsUnsignedLongLong(seed.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    throw InvalidArgument(
        detail::concat("self_affine_surface: seed = ", py::repr(seed).cast<std::string>(),
                       " must be an integer in 0 .. 2^64 - 1"));
  }
  return value;
}

py::array_t<double> self_affine(const Grid& grid, double hurst, std::optional<double> rms_height,
                                std::optional<double> rms_slope, std::optional<double> short_cutoff,
                                std::optional<double> long_cutoff, const py::int_& seed) {
  SelfAffineSpec spec;
  spec.hurst = hurst;
  spec.rms_height = rms_height;
  spec.rms_slope = rms_slope;
  spec.short_cutoff = short_cutoff;
  spec.long_cutoff = long_cutoff;
  spec.seed = seed_of(seed);
  // The memory first: the spectrum's sums of the check take minutes on the largest grids.
  require_self_affine_memory(grid, "self_affine_surface");
  check_self_affine_spec(grid, spec, "self_affine_surface: rms_height",
                         "self_affine_surface: rms_slope");
  return array_from_field(self_affine_surface(grid, spec));
}

// h of an indenter on `grid`, checked as a scene's [contact] indenter is.
template <class Shape>
py::array_t<double> height_of(const Grid& grid, const Shape& shape, const char* who) {
  require_grid_memory(grid.nx(), grid.ny(), 1.0, who);
  check_indenter(grid, shape);
  return array_from_field(height(grid, shape));
}

// Hertz's sphere (Johnson 1985, section 4.2.1) as a dict, from exactly one of load and approach.
py::dict hertz_sphere(double radius, double E_star, std::optional<double> load,
                      std::optional<double> approach) {
  COATFFT_REQUIRE(load.has_value() != approach.has_value(),
                  "hertz_sphere: give exactly one of load [N] and approach [m]");
  const HertzSphere h = load ? hertz_sphere_for_load(*load, radius, E_star)
                             : hertz_sphere_for_approach(*approach, radius, E_star);
  return py::dict("load"_a = h.load, "contact_radius"_a = h.contact_radius,
                  "max_pressure"_a = h.max_pressure, "approach"_a = h.approach);
}

}  // namespace

void bind_surfaces(py::module_& m) {
  m.def("self_affine_surface", &self_affine, "grid"_a, py::kw_only(), "hurst"_a,
        "rms_height"_a = py::none(), "rms_slope"_a = py::none(), "short_cutoff"_a = py::none(),
        "long_cutoff"_a = py::none(), "seed"_a = 0,
        "Heights h [m], shape (ny, nx), of a periodic self-affine random surface on `grid` (nx, "
        "ny even): Hurst exponent `hurst` in (0, 1], exactly one of `rms_height` [m] and "
        "`rms_slope` [-], wavelengths [m] from `short_cutoff` (default 2 max(dx, dy)) to the "
        "roll-off `long_cutoff` (default max(lx, ly)); the same `seed` (0 .. 2^64 - 1) gives the "
        "same surface as `coatfft surface`, bit for bit (docs/surfaces.md).");
  m.def(
      "sphere_height",
      [](const Grid& grid, double radius) {
        return height_of(grid, Sphere{radius}, "sphere_height");
      },
      "grid"_a, "radius"_a,
      "Initial separation h = R - sqrt(R^2 - r^2) [m], shape (ny, nx), of a rigid sphere of "
      "radius R [m] centred on the origin (its lowest point at h = 0).");
  m.def(
      "paraboloid_height",
      [](const Grid& grid, double radius) {
        return height_of(grid, Paraboloid{radius}, "paraboloid_height");
      },
      "grid"_a, "radius"_a, "h = r^2 / (2 R) [m], shape (ny, nx): Hertz's small-slope sphere.");
  m.def(
      "cylinder_height",
      [](const Grid& grid, double radius, double flat_length, double end_radius) {
        return height_of(grid, Cylinder{radius, flat_length, end_radius}, "cylinder_height");
      },
      "grid"_a, "radius"_a, py::kw_only(), "flat_length"_a, "end_radius"_a,
      "h = y^2 / (2 R) + max(|x| - L/2, 0)^2 / (2 Re) [m], shape (ny, nx): a roller along x "
      "of radius R [m], straight over the length L = flat_length [m], crowned by Re = "
      "end_radius [m] beyond.");
  m.def(
      "flat_punch_height",
      [](const Grid& grid, double radius, double edge_radius) {
        return height_of(grid, FlatPunch{radius, edge_radius}, "flat_punch_height");
      },
      "grid"_a, "radius"_a, py::kw_only(), "edge_radius"_a,
      "h = 0 for r <= a, (r - a)^2 / (2 rho) beyond [m], shape (ny, nx): a flat punch of radius "
      "a [m] with an edge rounded by rho = edge_radius [m].");
  m.def("hertz_sphere", &hertz_sphere, "radius"_a, "E_star"_a, py::kw_only(), "load"_a = py::none(),
        "approach"_a = py::none(),
        "Hertz's sphere of radius R [m] on a half-space of plane-strain modulus E_star [Pa] "
        "(Johnson 1985, section 4.2.1), under a load W [N] or an approach delta [m]: a dict of "
        "load [N], contact_radius a [m], max_pressure p0 [Pa] and approach [m].");
}

}  // namespace coatfft::python
