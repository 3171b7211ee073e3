// stresses and von_mises: the stresses on planes inside a body (stress/stress_operator.hpp) under
// a pressure and tangential tractions, as arrays of the layout of the program's stress.npy; and
// surface_displacements, the surface's (u_x, u_y, u_z) under the same loads
// (convolution/operators/cerruti_operator.hpp), as the program's ux.npy, uy.npy and uz.npy.
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "convolution/operators/make_operator.hpp"
#include "convolution/operators/operator_memory.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "stress/stress_invariants.hpp"
#include "stress/stress_operator.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace coatfft::python {

namespace {

InterfaceSide parse_side(const std::string& name) {
  if (name == "below") return InterfaceSide::below;
  if (name == "above") return InterfaceSide::above;
  throw InvalidArgument("stresses: at_interface = \"" + name +
                        "\" is not one of \"below\", \"above\"");
}

// The surface loads of a call: the pressure and the optional tractions, as fields of `grid`.
struct SurfaceLoads {
  Field p;
  std::optional<Field> qx, qy;
  const Field* x() const { return qx ? &*qx : nullptr; }
  const Field* y() const { return qy ? &*qy : nullptr; }
};

SurfaceLoads surface_loads(const std::string& who, const Grid& grid, const DoubleArray& pressure,
                           const std::optional<DoubleArray>& qx,
                           const std::optional<DoubleArray>& qy) {
  SurfaceLoads loads{field_from_array(pressure, grid, who + ": pressure"), {}, {}};
  if (qx) loads.qx = field_from_array(*qx, grid, who + ": qx");
  if (qy) loads.qy = field_from_array(*qy, grid, who + ": qy");
  return loads;
}

// The depths [m] of a 1-D array: a 2-D array is refused rather than flattened, whose planes would
// come back in an order the caller did not write.
std::vector<double> depth_list(const DoubleArray& depths) {
  COATFFT_REQUIRE(depths.ndim() == 1,
                  "stresses: depths must be a 1-D list of depths [m], not an "
                  "array of ",
                  depths.ndim(), " dimensions");
  std::vector<double> list(depths.data(), depths.data() + depths.size());
  require_stress_depths(list);
  return list;
}

// The program's memory refusal (core/memory.hpp) for `planes` planes and their output array.
void require_stress_memory(const Grid& grid, std::size_t planes, const StressOperatorOptions& o) {
  const double out = 6.0 * 8.0 * static_cast<double>(planes) * static_cast<double>(grid.nb_cells());
  const int alpha = o.kernel.alpha;
  const bool periodic = o.boundary == Boundary::periodic;
  require_memory({estimated_stress_bytes(grid, planes, alpha, o.tangential, o.boundary) + out,
                  periodic ? detail::concat("grid ", grid.nx(), " x ", grid.ny(), ", ", planes,
                                            " periodic planes")
                           : detail::concat("grid ", grid.nx(), " x ", grid.ny(), ", ", planes,
                                            " planes at alpha = ", alpha)},
                 std::nullopt, "stresses", "", "use fewer cells or fewer depths");
}

// boundary = "free" or "periodic", as [grid] boundary: whether it is periodic.
bool is_periodic(const std::string& boundary, const char* what) {
  COATFFT_REQUIRE(boundary == "free" || boundary == "periodic", what, ": boundary = \"", boundary,
                  "\" is not one of \"free\", \"periodic\"");
  return boundary == "periodic";
}

// The stresses' boundary; alpha, the free surface's sampling period, is refused on a periodic one
// (the program's [stress] alpha likewise).
bool periodic_stress(const std::string& boundary, const std::optional<int>& alpha) {
  const bool periodic = is_periodic(boundary, "stresses");
  COATFFT_REQUIRE(!periodic || !alpha,
                  "stresses: alpha sets the sampling lattice of a free surface's kernels; with "
                  "boundary = \"periodic\" they lie on the period's own lattice: leave it out");
  return periodic;
}

// (n_depths, 6, ny, nx) [Pa], components xx, yy, zz, yz, xz, xy, as stress.npy.
py::array_t<double> stresses(py::handle body_object, const Grid& grid,
                             const DoubleArray& depth_array, const DoubleArray& pressure,
                             const std::optional<DoubleArray>& qx,
                             const std::optional<DoubleArray>& qy, const std::string& at_interface,
                             const std::string& boundary, std::optional<int> alpha, int threads) {
  const LayerStack stack =
      layers_of(body_object, "stresses", "the fields at depth need the layers");
  const std::vector<double> depths = depth_list(depth_array);
  StressOperatorOptions options;
  options.side = parse_side(at_interface);
  options.boundary = periodic_stress(boundary, alpha) ? Boundary::periodic : Boundary::free;
  options.kernel.alpha = alpha.value_or(options.kernel.alpha);
  options.kernel.threads = threads;
  options.tangential = qx || qy;
  // Before the loads are copied: a grid too large is refused before anything is allocated.
  require_stress_memory(grid, depths.size(), options);
  const SurfaceLoads loads = surface_loads("stresses", grid, pressure, qx, qy);
  std::vector<double> values;
  without_gil([&] {
    std::vector<PlaneStress> planes;
    make_stress_operator(grid, stack, depths, options)
        ->apply(loads.p, loads.x(), loads.y(), planes);
    values.reserve(planes.size() * 6 * static_cast<std::size_t>(grid.nb_cells()));
    for (const PlaneStress& plane : planes)
      for (const Field& c : plane) values.insert(values.end(), c.data(), c.data() + c.size());
  });
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(depths.size()), 6, grid.ny(),
                                       grid.nx()};
  py::array_t<double> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// (ux, uy, uz) [m], each (ny, nx), of any bonded body under p, q_x, q_y.
py::tuple surface_displacements(py::handle body_object, const Grid& grid,
                                const DoubleArray& pressure, const std::optional<DoubleArray>& qx,
                                const std::optional<DoubleArray>& qy, const std::string& boundary,
                                int threads) {
  const LayerStack stack =
      layers_of(body_object, "surface_displacements", "the tangential response needs the layers");
  TangentialOptions options;
  options.boundary =
      is_periodic(boundary, "surface_displacements") ? Boundary::periodic : Boundary::free;
  // The operator, the loads' copies and the three outputs, before anything is allocated.
  require_memory({estimated_cerruti_bytes(grid) + 6.0 * 8.0 * static_cast<double>(grid.nb_cells()),
                  detail::concat("grid ", grid.nx(), " x ", grid.ny())},
                 std::nullopt, "surface_displacements", "", "use fewer cells");
  const SurfaceLoads loads = surface_loads("surface_displacements", grid, pressure, qx, qy);
  options.threads = threads;
  std::array<Field, 3> u;
  without_gil([&] {
    make_tangential_operator(grid, stack, options).op->apply(loads.p, loads.x(), loads.y(), u);
  });
  return py::make_tuple(array_from_field(std::move(u[0])), array_from_field(std::move(u[1])),
                        array_from_field(std::move(u[2])));
}

// `f` of every tensor of an array whose third axis from the end holds the six components, as
// stresses() returns them: that axis replaced by `width` values per point (removed for width 0:
// one value). f(tensor, values) writes max(width, 1) values.
template <class F>
py::array_t<double> per_tensor(const DoubleArray& stress, const char* name, int width, F f) {
  const py::ssize_t nd = stress.ndim();
  COATFFT_REQUIRE(nd >= 3 && stress.shape(nd - 3) == 6, name,
                  ": the array needs the six components (xx, yy, zz, yz, xz, xy) on its "
                  "third axis from the end, as stresses() returns them");
  std::vector<py::ssize_t> shape(stress.shape(), stress.shape() + nd);
  const py::ssize_t points = shape[nd - 2] * shape[nd - 1];
  py::ssize_t outer = 1;
  for (py::ssize_t a = 0; a < nd - 3; ++a) outer *= shape[a];
  if (width == 0)
    shape.erase(shape.begin() + (nd - 3));
  else
    shape[nd - 3] = width;
  const int values = std::max(width, 1);
  py::array_t<double> out(shape);
  const double* s = stress.data();
  double* v = out.mutable_data();
  std::array<double, 3> result{};
  for (py::ssize_t o = 0; o < outer; ++o)
    for (py::ssize_t q = 0; q < points; ++q) {
      StressVector t;
      for (int c = 0; c < 6; ++c) t[c] = s[(o * 6 + c) * points + q];
      f(t, result);
      for (int c = 0; c < values; ++c) v[(o * values + c) * points + q] = result[c];
    }
  return out;
}

py::array_t<double> von_mises_of(const DoubleArray& stress) {
  return per_tensor(stress, "von_mises", 0,
                    [](const StressVector& t, std::array<double, 3>& r) { r[0] = von_mises(t); });
}

py::array_t<double> principal_stresses_of(const DoubleArray& stress) {
  return per_tensor(
      stress, "principal_stresses", 3,
      [](const StressVector& t, std::array<double, 3>& r) { r = principal_stresses(t); });
}

py::array_t<double> tresca_of(const DoubleArray& stress) {
  return per_tensor(stress, "tresca", 0,
                    [](const StressVector& t, std::array<double, 3>& r) { r[0] = tresca(t); });
}

}  // namespace

void bind_stress(py::module_& m) {
  m.def("stresses", &stresses, py::arg("body"), py::arg("grid"), py::arg("depths"),
        py::arg("pressure"), py::arg("qx") = py::none(), py::arg("qy") = py::none(), py::kw_only(),
        py::arg("at_interface") = "below", py::arg("boundary") = "free",
        py::arg("alpha") = py::none(), py::arg("threads") = 1,
        "Stresses [Pa] on the planes z = depths [m] inside `body` (a LayerStack or Material) "
        "under the pressure (compression positive) and the tractions qx, qy the surface "
        "receives, each (ny, nx) [Pa] of `grid`: an array (n_depths, 6, ny, nx), components xx, "
        "yy, zz, yz, xz, xy, tension positive, z into the body (docs/stress.md). boundary = "
        "\"periodic\": the loads repeat over the grid's domain (nx, ny even; the mean stress "
        "is that under a wide uniformly loaded disc, docs/stress.md); alpha (default 16) is the "
        "free surface's sampling period.");
  m.def("surface_displacements", &surface_displacements, py::arg("body"), py::arg("grid"),
        py::arg("pressure"), py::arg("qx") = py::none(), py::arg("qy") = py::none(), py::kw_only(),
        py::arg("boundary") = "free", py::arg("threads") = 1,
        "Surface displacements (ux, uy, uz) [m], each (ny, nx), of `body` (a LayerStack with "
        "bonded interfaces, or a Material) under the pressure and the tractions qx, qy [Pa] of "
        "`grid`, uz into the body (docs/stress.md, 'Surface displacements'). boundary = "
        "\"periodic\": the loads repeat over the grid's domain (nx, ny even); every displacement "
        "then has zero mean over the period.");
  m.def("von_mises", &von_mises_of, py::arg("stress"),
        "von Mises stress [Pa] of an array of stresses(), the component axis removed.");
  m.def("principal_stresses", &principal_stresses_of, py::arg("stress"),
        "The principal stresses [Pa], largest first (tension positive), of an array of "
        "stresses(): the component axis (6) replaced by the three values, e.g. (n_depths, 3, ny, "
        "nx).");
  m.def("tresca", &tresca_of, py::arg("stress"),
        "Tresca's maximum shear stress (s1 - s3)/2 [Pa] of an array of stresses(), the component "
        "axis removed.");
}

}  // namespace coatfft::python
