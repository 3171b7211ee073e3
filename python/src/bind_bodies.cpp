// Materials, layer stacks and FRFs: Material, material, Coating, LayerStack, Frf, UserFrf,
// TabulatedFrf, frf.
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "core/error.hpp"
#include "frf/tabulated_frf.hpp"
#include "materials/catalog.hpp"
#include "user_frf.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

std::shared_ptr<const Frf> Body::response() const {
  if (frf) return frf;
  return make_frf(*stack);
}

Body body_from_object(py::handle object, const char* what) {
  if (py::isinstance<LayerStack>(object)) return {object.cast<LayerStack>(), nullptr};
  if (py::isinstance<Material>(object)) return {LayerStack(object.cast<Material>()), nullptr};
  if (py::isinstance<Frf>(object)) return {std::nullopt, object.cast<std::shared_ptr<Frf>>()};
  throw py::type_error(std::string(what) +
                       ": expected a LayerStack, a Material or an Frf (UserFrf, TabulatedFrf), "
                       "not " +
                       py::str(py::type::of(object).attr("__name__")).cast<std::string>());
}

LayerStack layers_of(py::handle body_object, const std::string& who, const char* why) {
  const Body body = body_from_object(body_object, "body");
  COATFFT_REQUIRE(body.stack, who, ": body must be a LayerStack or a Material (", why,
                  "), not an Frf");
  return *body.stack;
}

namespace {

// H(k) of any FRF at every k of a numpy array, in one batch, without the GIL (a UserFrf takes
// it back for its own calls).
py::array_t<double> evaluate_frf(const Frf& frf, const DoubleArray& k) {
  std::vector<double> h(static_cast<std::size_t>(k.size()));
  const std::span<const double> ks(k.data(), h.size());
  for (const double ki : ks)
    COATFFT_REQUIRE(std::isfinite(ki) && ki > 0, "frf: k = ", ki,
                    " rad/m, but every wavenumber must be finite and > 0");
  without_gil([&] { frf.evaluate(ks, h); });
  return array_like(k, std::move(h));
}

Interface parse_interface(std::string_view name) {
  if (name == "bonded") return Interface::bonded;
  if (name == "frictionless") return Interface::frictionless;
  throw InvalidArgument(detail::concat("Coating: interface = \"", name,
                                       "\" is not one of \"bonded\", \"frictionless\""));
}

// Python's repr of a double: the shortest text that reads back to the same bits.
std::string float_repr(double x) {
  return py::repr(py::float_(x)).cast<std::string>();
}

const char* interface_name(Interface interface) {
  return interface == Interface::bonded ? "bonded" : "frictionless";
}

// The reprs are constructor calls, so that eval(repr(x)) == x.
std::string repr(const Material& m) {
  return "Material(E=" + float_repr(m.youngs_modulus()) + ", nu=" + float_repr(m.poisson_ratio()) +
         ")";
}

std::string repr(const Coating& c) {
  return "Coating(" + repr(c.material) + ", thickness=" + float_repr(c.thickness) +
         ", interface=\"" + interface_name(c.interface_below) + "\")";
}

std::string repr(const LayerStack& s) {
  std::string coatings;
  for (const Coating& c : s.coatings()) coatings += (coatings.empty() ? "" : ", ") + repr(c);
  return "LayerStack(" + repr(s.substrate()) + ", [" + coatings + "])";
}

// The library has no operator== for these (it never compares bodies); Python values do.
bool equal(const Coating& a, const Coating& b) {
  return a.material == b.material && a.thickness == b.thickness &&
         a.interface_below == b.interface_below;
}

bool equal(const LayerStack& a, const LayerStack& b) {
  return a.substrate() == b.substrate() &&
         std::equal(a.coatings().begin(), a.coatings().end(), b.coatings().begin(),
                    b.coatings().end(),
                    [](const Coating& x, const Coating& y) { return equal(x, y); });
}

void bind_material(py::module_& m) {
  py::class_<Material>(m, "Material", "An isotropic linear-elastic material.")
      .def(py::init<double, double>(), "E"_a, "nu"_a,
           "Young's modulus E [Pa] (> 0) and Poisson's ratio nu (-1 < nu <= 0.4999).")
      .def_property_readonly("E", &Material::youngs_modulus, "Young's modulus [Pa]")
      .def_property_readonly("nu", &Material::poisson_ratio, "Poisson's ratio [-]")
      .def_property_readonly("E_star", &Material::plane_strain_modulus,
                             "plane-strain modulus E / (1 - nu^2) [Pa]")
      .def_property_readonly("shear_modulus", &Material::shear_modulus, "E / (2 (1 + nu)) [Pa]")
      // is_operator: another type gives NotImplemented, so that m == 3 is False, not TypeError.
      .def(
          "__eq__", [](const Material& a, const Material& b) { return a == b; }, py::is_operator())
      .def("__repr__", py::overload_cast<const Material&>(&repr));
  m.def("material", &material_by_name, "name"_a,
        "The catalogue's material of that name (\"steel\", \"titanium_nitride\", ...; "
        "material_names()).");
  m.def("material_names", &material_names, "The names of the catalogue's materials.");
}

void bind_stack(py::module_& m) {
  py::class_<Coating>(m, "Coating", "A coating of a layer stack, and its interface below.")
      .def(py::init([](const Material& material, double thickness, std::string_view interface) {
             // Refused here, where it is written, rather than when a LayerStack gets it.
             COATFFT_REQUIRE(std::isfinite(thickness) && thickness > 0,
                             "Coating: thickness = ", thickness,
                             " m, but it must be finite and > 0");
             return Coating{material, thickness, parse_interface(interface)};
           }),
           "material"_a, "thickness"_a, "interface"_a = "bonded",
           "thickness [m]; interface with the medium below: \"bonded\" or \"frictionless\".")
      .def_readonly("material", &Coating::material)
      .def_readonly("thickness", &Coating::thickness)
      .def_property_readonly("interface",
                             [](const Coating& c) { return interface_name(c.interface_below); })
      .def("__eq__", py::overload_cast<const Coating&, const Coating&>(&equal), py::is_operator())
      .def("__repr__", py::overload_cast<const Coating&>(&repr));
  py::class_<LayerStack>(m, "LayerStack", "Coatings (top first) on a homogeneous substrate.")
      .def(py::init([](const Material& substrate, std::vector<Coating> coatings) {
             return LayerStack(std::move(coatings), substrate);
           }),
           "substrate"_a, "coatings"_a = std::vector<Coating>{})
      .def_property_readonly("substrate", &LayerStack::substrate)
      .def_property_readonly("coatings", &LayerStack::coatings)
      .def_property_readonly("is_homogeneous", &LayerStack::is_homogeneous)
      .def_property_readonly("total_thickness", &LayerStack::total_thickness, "[m]")
      .def_property_readonly("interface_depths", &LayerStack::interface_depths,
                             "depths [m] of the interfaces, top first (running sums of the "
                             "thicknesses): a depth within 256 DBL_EPSILON of one is that "
                             "interface")
      .def("__eq__", py::overload_cast<const LayerStack&, const LayerStack&>(&equal),
           py::is_operator())
      .def("__repr__", py::overload_cast<const LayerStack&>(&repr));
}

void bind_frfs(py::module_& m) {
  py::class_<Frf, std::shared_ptr<Frf>>(m, "Frf", "A frequency response function H(k) [m/Pa].")
      .def("__call__", &evaluate_frf, "k"_a, "H at every k [rad/m] of an array")
      .def_property_readonly("c0", &Frf::c0, "lim k H(k) at k -> 0 [1/Pa]")
      .def_property_readonly("c_inf", &Frf::c_inf, "lim k H(k) at k -> inf [1/Pa]")
      .def_property_readonly("name", &Frf::name)
      .def("__repr__", [](const py::object& self) {
        const Frf& f = self.cast<const Frf&>();
        return py::str("{}(name={!r}, c0={!r}, c_inf={!r})")
            .format(py::type::of(self).attr("__name__"), f.name(), f.c0(), f.c_inf());
      });
  py::class_<UserFrf, Frf, std::shared_ptr<UserFrf>>(m, "UserFrf")
      .def(py::init<py::function, double, double>(), "function"_a, "c0"_a, "c_inf"_a,
           "An FRF given by function(k) -> H for a float64 array k [rad/m]; c0, c_inf [1/Pa].")
      .def_property_readonly("function", &UserFrf::function)
      .def_property_readonly("calls", &UserFrf::calls, "calls of the function so far");
  py::class_<TabulatedFrf, Frf, std::shared_ptr<TabulatedFrf>>(m, "TabulatedFrf")
      .def(py::init([](std::vector<double> k, std::vector<double> H, std::optional<double> c0,
                       std::optional<double> c_inf) {
             auto table = std::make_shared<TabulatedFrf>(std::move(k), std::move(H), c0, c_inf);
             // A given limit far from the table's end: RuntimeWarning, as the program warns.
             for (const std::string& warning : table->warnings())
               warn_each(py::make_tuple("TabulatedFrf: " + warning));
             return table;
           }),
           "k"_a, "H"_a, "c0"_a = py::none(), "c_inf"_a = py::none(),
           "An FRF from a table: k [rad/m] ascending, H [m/Pa]; c0, c_inf estimated when not "
           "given, refused when more than 10 times off the table's ends (RuntimeWarning above "
           "1 %).")
      .def_property_readonly("c0_estimated", &TabulatedFrf::c0_estimated)
      .def_property_readonly("c_inf_estimated", &TabulatedFrf::c_inf_estimated);
  m.def(
      "frf",
      [](py::handle body, const DoubleArray& k) {
        return evaluate_frf(*body_from_object(body).response(), k);
      },
      "body"_a, "k"_a, "H(k) [m/Pa] of a body at every k [rad/m] of an array.");
}

}  // namespace

void bind_bodies(py::module_& m) {
  bind_material(m);
  bind_stack(m);
  bind_frfs(m);
}

}  // namespace coatfft::python
