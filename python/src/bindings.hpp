#pragma once
// The parts of the module, one per concept, each in its bind_*.cpp.
#include <pybind11/pybind11.h>

#include <string_view>

namespace coatfft::python {

void bind_bodies(pybind11::module_& m);        // Material, Coating, LayerStack, Frf, UserFrf, frf
void bind_loads(pybind11::module_& m);         // Grid, pressures, closed-form and Hankel references
void bind_operator(pybind11::module_& m);      // make_operator, Operator
void bind_contact(pybind11::module_& m);       // solve_contact, ContactResult
void bind_partial_slip(pybind11::module_& m);  // solve_partial_slip, PartialSlipResult
void bind_scene(pybind11::module_& m);         // run_scene, validate_frf
void bind_stress(pybind11::module_& m);        // stresses, von_mises, surface_displacements
void bind_timing(pybind11::module_& m);        // the C++ side of bench/bench_python.py
void bind_topography(pybind11::module_& m);    // read_topography
void bind_surfaces(pybind11::module_& m);  // self_affine_surface, indenter heights, hertz_sphere

/// A Python dict from JSON (the CLI's summary and reports), through the json module: numbers
/// keep every bit, null becomes None.
pybind11::dict dict_from_json_text(std::string_view text);

/// Each string of the list `warnings` as a RuntimeWarning (where the CLI prints them on stderr);
/// throws error_already_set when a warnings filter turns one into an exception.
void warn_each(pybind11::handle warnings);

}  // namespace coatfft::python
