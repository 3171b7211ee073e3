#include "user_frf.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace py = pybind11;

namespace coatfft::python {

UserFrf::UserFrf(py::function function, double c0, double c_inf)
    : function_(std::move(function)), c0_(c0), c_inf_(c_inf) {
  COATFFT_REQUIRE(std::isfinite(c0) && c0 > 0, "UserFrf: c0 = ", c0,
                  " 1/Pa, but it must be finite and > 0 (lim k H(k) at k -> 0, 2/E* of the "
                  "substrate)");
  COATFFT_REQUIRE(std::isfinite(c_inf) && c_inf > 0, "UserFrf: c_inf = ", c_inf,
                  " 1/Pa, but it must be finite and > 0 (lim k H(k) at k -> inf, 2/E* of the top "
                  "layer)");
}

double UserFrf::operator()(double k) const {
  double h = 0.0;
  evaluate(std::span<const double>(&k, 1), std::span<double>(&h, 1));
  return h;
}

void UserFrf::evaluate(std::span<const double> k, std::span<double> h) const {
  COATFFT_REQUIRE(k.size() == h.size(), "UserFrf: ", k.size(), " wavenumbers but room for ",
                  h.size(), " values");
  if (k.empty()) return;
  py::gil_scoped_acquire gil;
  ++calls_;
  py::array_t<double> ks(static_cast<py::ssize_t>(k.size()));
  std::copy(k.begin(), k.end(), ks.mutable_data());
  const py::object result = function_(ks);
  // Numbers only: a cast to float64 would read None as NaN (a ValueError about H, not the type
  // error it is), strings of digits as numbers and complex values as their real parts.
  const py::array as_array = py::module_::import("numpy").attr("asarray")(result);
  const char kind = as_array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error("UserFrf: the function returned " +
                         py::str(py::type::of(result).attr("__name__")).cast<std::string>() +
                         " (dtype " + py::str(as_array.dtype()).cast<std::string>() +
                         "), not an array of real numbers H");
  const auto values =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(as_array);
  COATFFT_REQUIRE(values.ndim() == 1 && static_cast<std::size_t>(values.size()) == k.size(),
                  "UserFrf: the function returned ", values.size(), " values in ", values.ndim(),
                  " dimensions for ", k.size(), " wavenumbers; it must return one H per k");
  const double* v = values.data();
  for (std::size_t i = 0; i < k.size(); ++i) {
    COATFFT_REQUIRE(std::isfinite(v[i]) && v[i] > 0, "UserFrf: the function gives H(", k[i],
                    " rad/m) = ", v[i], " m/Pa, but H must be finite and > 0");
    h[i] = v[i];
  }
}

}  // namespace coatfft::python
