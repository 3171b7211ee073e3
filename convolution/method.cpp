#include "convolution/method.hpp"

#include "core/detail/parse_name.hpp"
#include "core/error.hpp"

namespace coatfft {

std::string_view to_string(Method method) {
  switch (method) {
    case Method::direct:
      return "direct";
    case Method::dcfft:
      return "dcfft";
    case Method::frf_spectral:
      return "frf-spectral";
    case Method::frf_dcfft:
      return "frf-dcfft";
    case Method::frf_split:
      return "frf-split";
  }
  throw InvalidArgument("to_string: not a Method");
}

Method parse_method(std::string_view name) {
  return detail::parse_name(name, all_methods);
}

std::string_view to_string(Boundary boundary) {
  return boundary == Boundary::periodic ? "periodic" : "free";
}

Boundary parse_boundary(std::string_view name) {
  return detail::parse_name(name, std::array{Boundary::free, Boundary::periodic});
}

bool uses_love_coefficients(Method method) {
  return method == Method::direct || method == Method::dcfft;
}

bool samples_frf_lattice(Method method) {
  return method == Method::frf_spectral || method == Method::frf_dcfft;
}

}  // namespace coatfft
