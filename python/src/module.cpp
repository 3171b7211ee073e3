// The extension module coatfft._coatfft: its parts, and the mapping of the library's errors to
// Python's (docs/python.md): InvalidArgument is ValueError with the library's message, any other
// coatfft::Error RuntimeError; pybind11 itself raises TypeError for arguments of the wrong type.
// A call stopped by Ctrl-C raises KeyboardInterrupt (python/src/without_gil.hpp).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace py = pybind11;

namespace coatfft::python {

py::dict dict_from_json_text(std::string_view text) {
  return py::module_::import("json").attr("loads")(py::str(text.data(), text.size()));
}

void warn_each(py::handle warnings) {
  for (const py::handle warning : warnings)
    if (PyErr_WarnEx(PyExc_RuntimeWarning, py::str(warning).cast<std::string>().c_str(), 1) < 0)
      throw py::error_already_set();
}

}  // namespace coatfft::python

PYBIND11_MODULE(_coatfft, m) {
  m.doc() = "coatfft: surface displacements and contact of coated and layered elastic bodies";
  m.attr("__version__") = COATFFT_VERSION;
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const coatfft::Interrupted&) {
      // Stopped by a hook without an exception of Python's to raise (python/src/without_gil.hpp
      // raises the handler's own): what Ctrl-C raises.
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const coatfft::InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const coatfft::Error& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
  coatfft::python::bind_bodies(m);
  coatfft::python::bind_loads(m);
  coatfft::python::bind_operator(m);
  coatfft::python::bind_contact(m);
  coatfft::python::bind_partial_slip(m);
  coatfft::python::bind_scene(m);
  coatfft::python::bind_stress(m);
  coatfft::python::bind_timing(m);
  coatfft::python::bind_surfaces(m);
  coatfft::python::bind_topography(m);
}
